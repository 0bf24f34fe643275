#pragma once
// The one exception type for bad input (leaf files, grids that violate a precondition).
// The CLI maps it to exit code 3. Bad input must never crash or assert: it throws this.
#include <stdexcept>
#include <string>

namespace dualhex {

class InputError : public std::runtime_error {
public:
    /// `file` may be empty (input not read from a file); `line` is 1-based, 0 if none.
    /// `message` names the offending entity (a leaf "L i j k", a token, a line's text).
    /// what() is "file:line: message", "file: message" or just "message".
    InputError(std::string file, int line, std::string message);

    [[nodiscard]] const std::string& file() const { return file_; }
    [[nodiscard]] int line() const { return line_; }
    [[nodiscard]] const std::string& message() const { return message_; }

private:
    std::string file_;
    int line_;
    std::string message_;
};

}  // namespace dualhex
