#include "dualhex/grid/input_error.hpp"

#include <utility>

namespace dualhex {

namespace {
std::string format(const std::string& file, int line, const std::string& message) {
    if (file.empty()) return line > 0 ? "line " + std::to_string(line) + ": " + message : message;
    return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
}
}  // namespace

InputError::InputError(std::string file, int line, std::string message)
    : std::runtime_error(format(file, line, message)), file_(std::move(file)), line_(line), message_(std::move(message)) {}

}  // namespace dualhex
