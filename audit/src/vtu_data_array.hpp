#pragma once
// The values of one VTU DataArray: format="ascii" (whitespace-separated numbers),
// format="binary" (inline base64 of a byte-count header, UInt32 or UInt64, then the
// little-endian values; header and data may be encoded as one base64 block or two) or
// format="appended" offset="N" (the same header and values at byte N of <AppendedData>,
// raw, or base64 with header and data encoded separately).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "xml_scan.hpp"

namespace dualhex::audit::detail {

struct VtuFileInfo {
    bool header_uint64 = false;  ///< header_type="UInt64"
    /// <AppendedData>: the bytes after its '_' (to the end of the file), its encoding, and
    /// the line of the '_' (for messages). Empty data: no appended section.
    std::string_view appended;
    bool appended_base64 = false;
    int appended_line = 0;
};

struct DataArrayValues {
    std::vector<double> reals;          ///< if read as reals
    std::vector<std::int64_t> ints;     ///< if read as integers
    std::vector<int> lines;             ///< ascii: the line of each value; binary: empty
    int tag_line = 0;
};

inline constexpr std::size_t kAnyCount = static_cast<std::size_t>(-1);

/// Reads exactly `expected` values (kAnyCount: all there are) (InputError otherwise, naming the array and line).
/// `as_int`: integers (a Float type is an error), else reals.
[[nodiscard]] DataArrayValues read_data_array(XmlScanner& xml, const XmlTag& tag, const VtuFileInfo& info,
                                              std::size_t expected, bool as_int, const std::string& what);

/// Strict base64 (RFC 4648 alphabet, '=' padding; blocks may be concatenated; whitespace
/// ignored). Returns false on a bad character.
[[nodiscard]] bool decode_base64(std::string_view text, std::vector<unsigned char>& out);

}  // namespace dualhex::audit::detail
