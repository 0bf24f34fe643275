#pragma once
// Whitespace-separated tokens of a text (a whole file, or one XML element's content) with
// the line each token is on, and strict number parsing: every failure is an InputError
// naming the file, the line and the offending token.
#include <cstdint>
#include <string>
#include <string_view>

#include "dualhex/grid/input_error.hpp"

namespace dualhex::audit::detail {

/// The file's bytes. InputError if it is missing, not a regular file, or unreadable.
[[nodiscard]] std::string read_regular_file(const std::string& path);

class TextScanner {
public:
    /// `text` must outlive the scanner; `first_line` is the line `text` starts on;
    /// `comment` (if not 0) starts a comment running to the end of the line.
    TextScanner(std::string path, std::string_view text, int first_line = 1, char comment = 0);

    /// The next token, or false at the end.
    bool next(std::string_view& token);
    /// The next token; InputError "unexpected end of file, expected WHAT" at the end.
    std::string_view expect(std::string_view what);
    /// The rest of the current line (after the last token), trimmed; advances past it.
    std::string_view rest_of_line();
    /// Whole-token integer / finite double; InputError naming WHAT and the token.
    std::int64_t read_int(std::string_view what);
    double read_double(std::string_view what);
    /// read_int, and in [lo, hi].
    std::int64_t read_int_in(std::string_view what, std::int64_t lo, std::int64_t hi);
    /// InputError unless `count` items of at least `tokens_each` tokens can fit in what is
    /// left of the text (every token takes >= 2 bytes with its separator): the check that
    /// stops a bad count from allocating before the truncation is noticed.
    void check_count(std::int64_t count, std::int64_t tokens_each, std::string_view what) const;

    /// Binary data: skips the rest of the current line (blanks only) and its newline, then
    /// returns the next `n` bytes (InputError "truncated" if fewer are left). Newline bytes
    /// inside still count as lines, so later line numbers match a byte-wise line count.
    std::string_view take_bytes(std::size_t n, std::string_view what);

    [[nodiscard]] int line() const { return token_line_; }  ///< line of the last token
    [[nodiscard]] const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const;
    /// Skips blanks and comments; true if nothing is left.
    bool at_end();

private:
    void skip_blanks();
    std::string path_;
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1, token_line_ = 1;
    char comment_ = 0;
};

/// "'tok'" shortened to 40 characters, for messages.
[[nodiscard]] std::string quote(std::string_view token);

}  // namespace dualhex::audit::detail
