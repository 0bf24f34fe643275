#include "dualhex/grid/input_error.hpp"

#include <utility>

namespace dualhex {

namespace {
// Control bytes as \xNN: a NUL in a quoted line would otherwise end what() early, and an
// escape sequence could rewrite the terminal.
std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c != 0x7f) {
            out += ch;
            continue;
        }
        static const char* hex = "0123456789abcdef";
        out += "\\x";
        out += hex[c >> 4];
        out += hex[c & 15];
    }
    return out;
}

std::string format(const std::string& file, int line, const std::string& message) {
    if (file.empty()) return line > 0 ? "line " + std::to_string(line) + ": " + message : message;
    return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
}
}  // namespace

InputError::InputError(std::string file, int line, std::string message)
    : std::runtime_error(format(printable(file), line, printable(message))),
      file_(std::move(file)),
      line_(line),
      message_(printable(message)) {}

}  // namespace dualhex
