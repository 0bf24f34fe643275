#pragma once
// The numbers of one VTK legacy data block, ASCII (tokens) or BINARY (big-endian values of
// the declared type right after the block's header line).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "text_scanner.hpp"

namespace dualhex::audit::detail {

class LegacyValues {
public:
    /// A block of `count` values of VTK type `type` ("float", "double", "int",
    /// "vtktypeint64", ...); checks the count against the file before anything is read.
    LegacyValues(TextScanner& in, bool binary, std::int64_t count, std::string_view type, std::string_view what)
        : in_(in), binary_(binary), what_(what) {
        in.check_count(count, binary ? 0 : 1, what);
        if (!binary) return;
        size_ = type == "double" || type == "vtktypeint64" || type == "vtktypeuint64" ? 8
                : type == "float" || type == "int" || type == "vtktypeint32" || type == "unsigned_int" ? 4
                                                                                                          : 0;
        if (size_ == 0) in.fail("unsupported binary data type " + quote(type) + " for " + std::string(what));
        real_ = type == "float" || type == "double";
        const auto n = static_cast<std::uint64_t>(count);
        if (n > (UINT64_MAX / 8)) in.fail(std::string(what) + " count " + std::to_string(count) + " too large");
        block_ = in.take_bytes(static_cast<std::size_t>(n) * static_cast<std::size_t>(size_), what);
    }

    std::int64_t read_int(std::string_view what) {
        if (!binary_) return in_.read_int(what);
        if (real_) in_.fail("binary " + std::string(what_) + " must be an integer type");
        const std::uint64_t bits = next_bits();
        if (size_ == 4) return static_cast<std::int32_t>(static_cast<std::uint32_t>(bits));
        return static_cast<std::int64_t>(bits);
    }

    double read_double(std::string_view what) {
        if (!binary_) return in_.read_double(what);
        const std::uint64_t bits = next_bits();
        double v = 0;
        if (!real_) {
            v = size_ == 4 ? static_cast<double>(static_cast<std::int32_t>(bits)) : static_cast<double>(static_cast<std::int64_t>(bits));
        } else if (size_ == 4) {
            const auto b = static_cast<std::uint32_t>(bits);
            float f;
            std::memcpy(&f, &b, 4);
            v = f;
        } else {
            std::memcpy(&v, &bits, 8);
        }
        if (!std::isfinite(v)) in_.fail("binary " + std::string(what) + " " + std::to_string(index_ - 1) + " is not finite");
        return v;
    }

    [[nodiscard]] int line() const { return in_.line(); }

private:
    std::uint64_t next_bits() {  // big-endian
        std::uint64_t v = 0;
        for (int i = 0; i < size_; ++i) v = (v << 8) | static_cast<unsigned char>(block_[index_ * static_cast<std::size_t>(size_) + static_cast<std::size_t>(i)]);
        ++index_;
        return v;
    }
    TextScanner& in_;
    bool binary_;
    std::string what_;
    std::string_view block_;
    int size_ = 0;
    bool real_ = false;
    std::size_t index_ = 0;
};

}  // namespace dualhex::audit::detail
