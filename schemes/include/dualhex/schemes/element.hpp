#pragma once
// Atomic elements as data (DESIGN.md sections 2, 7, 8): the in-memory form of an
// `.element` file, its parser and writer, and the conversion to a CellComplex.
//
// File format (version 1, documented in schemes/README.md):
//   # comment                      ('#' to end of line, anywhere)
//   dualhex-element 1              first directive: the format version
//   name F                         element name ([A-Za-z0-9_+.-]+)
//   leaf 12                        lattice resolution: the leaf is [0,leaf]^3, the
//                                  application point is the origin
//   vertex <id> x y z              integers, id >= 0 unique, 0 <= x,y,z <= leaf,
//                                  positions unique
//   cell <label>                   opens a cell (label unique)
//   face v0 v1 v2 ...              >= 3 declared vertex ids, counter-clockwise seen
//                                  from outside the cell
//   end                            closes the cell (at least one face)
// Every error is a SchemeFormatError naming file, line and the offending entity.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/lattice.hpp"

namespace dualhex {

/// The format version this library reads and writes.
inline constexpr int kElementFormatVersion = 1;

/// A malformed `.element` file (or an element that fails validation at load time).
/// what() is "file:line: message", "file: message" (line 0) or "message" (no file).
class SchemeFormatError : public std::runtime_error {
public:
    SchemeFormatError(std::string file, int line, std::string message);
    [[nodiscard]] const std::string& file() const { return file_; }
    [[nodiscard]] int line() const { return line_; }
    [[nodiscard]] const std::string& message() const { return message_; }

private:
    std::string file_;
    int line_;
    std::string message_;
};

struct ElementVertex {
    std::int64_t id = 0;
    LatticePoint position;
    bool operator==(const ElementVertex&) const = default;
};

struct ElementCell {
    std::string label;
    /// Vertex-id loops, counter-clockwise seen from outside the cell.
    std::vector<std::vector<std::int64_t>> faces;
    bool operator==(const ElementCell&) const = default;
};

/// An element exactly as written in its file (ids as in the file, order preserved).
struct ElementData {
    std::string name;
    std::int64_t leaf = 0;
    std::vector<ElementVertex> vertices;
    std::vector<ElementCell> cells;
    bool operator==(const ElementData&) const = default;
};

/// Parses an element; `file` is used in error messages only.
[[nodiscard]] ElementData parse_element(std::istream& in, const std::string& file = "<input>");
[[nodiscard]] ElementData parse_element_string(const std::string& text, const std::string& file = "<string>");
/// Reads and parses a file (SchemeFormatError if it cannot be opened).
[[nodiscard]] ElementData read_element_file(const std::filesystem::path& path);

/// Writes the canonical text form (parse_element(write_element(d)) == d for any d that
/// parses). Optional comment lines go right after a generated header comment.
void write_element(std::ostream& out, const ElementData& element, const std::vector<std::string>& comments = {});
[[nodiscard]] std::string element_to_string(const ElementData& element);

/// The complex of an element: vertex k of the complex is element.vertices[k], cell k is
/// element.cells[k]; faces are welded/deduplicated by ComplexBuilder, so a face shared by
/// two cells is one face used from both sides. Throws SchemeFormatError (no line) if a
/// face names an unknown vertex id or two vertices share a position (the parser already
/// rejects both; this guards hand-built ElementData).
[[nodiscard]] CellComplex to_complex(const ElementData& element);

/// The inverse direction: vertex ids = complex vertex indices, cells labelled by
/// `labels` (or "c<k>"), faces as the cells' outward half-face loops.
[[nodiscard]] ElementData element_from_complex(const std::string& name, std::int64_t leaf, const CellComplex& complex,
                                               const std::vector<std::string>& labels = {});

}  // namespace dualhex
