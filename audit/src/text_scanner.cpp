#include "text_scanner.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace dualhex::audit::detail {

std::string read_regular_file(const std::string& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw InputError(path, 0, "no such file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(path, 0, "not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot open for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError(path, 0, "read failed");
    return std::move(ss).str();
}

std::string quote(std::string_view token) {
    std::string s(token.substr(0, 40));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    return "'" + s + (token.size() > 40 ? "...'" : "'");
}

TextScanner::TextScanner(std::string path, std::string_view text, int first_line, char comment)
    : path_(std::move(path)), text_(text), line_(first_line), token_line_(first_line), comment_(comment) {}

void TextScanner::fail(const std::string& message) const { throw InputError(path_, token_line_, message); }

void TextScanner::skip_blanks() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '\n') {
            ++line_;
            ++pos_;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++pos_;
        } else if (comment_ != 0 && c == comment_) {
            while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        } else {
            return;
        }
    }
}

bool TextScanner::at_end() {
    skip_blanks();
    return pos_ >= text_.size();
}

bool TextScanner::next(std::string_view& token) {
    skip_blanks();
    token_line_ = line_;
    if (pos_ >= text_.size()) {  // the end: name the last line, not the empty one after it
        if (!text_.empty() && text_.back() == '\n' && token_line_ > 1) --token_line_;
        return false;
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
           !(comment_ != 0 && text_[pos_] == comment_))
        ++pos_;
    token = text_.substr(start, pos_ - start);
    return true;
}

std::string_view TextScanner::expect(std::string_view what) {
    std::string_view t;
    if (!next(t)) fail("unexpected end of file, expected " + std::string(what));
    return t;
}

std::string_view TextScanner::rest_of_line() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    std::string_view s = text_.substr(start, pos_ - start);
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

std::string_view TextScanner::take_bytes(std::size_t n, std::string_view what) {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) ++pos_;
    if (pos_ < text_.size() && text_[pos_] != '\n')
        fail("unexpected " + quote(text_.substr(pos_, 1)) + " before the binary " + std::string(what));
    if (pos_ < text_.size()) {
        ++pos_;
        ++line_;
    }
    token_line_ = line_;
    if (text_.size() - pos_ < n)
        fail("truncated binary " + std::string(what) + ": " + std::to_string(n) + " bytes expected, " +
             std::to_string(text_.size() - pos_) + " left");
    const std::string_view block = text_.substr(pos_, n);
    pos_ += n;
    for (char c : block) line_ += c == '\n' ? 1 : 0;
    return block;
}

std::int64_t TextScanner::read_int(std::string_view what) {
    const std::string_view t = expect(what);
    std::int64_t v = 0;
    const char* first = t.data();
    if (!t.empty() && t.front() == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), v);
    if (ec != std::errc() || ptr != t.data() + t.size())
        fail("bad " + std::string(what) + " " + quote(t) + " (expected an integer)");
    return v;
}

std::int64_t TextScanner::read_int_in(std::string_view what, std::int64_t lo, std::int64_t hi) {
    const std::int64_t v = read_int(what);
    if (v < lo || v > hi)
        fail(std::string(what) + " " + std::to_string(v) + " out of range [" + std::to_string(lo) + ", " +
             std::to_string(hi) + "]");
    return v;
}

double TextScanner::read_double(std::string_view what) {
    const std::string_view t = expect(what);
    double v = 0;
    const char* first = t.data();
    if (!t.empty() && t.front() == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), v);
    if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(v))
        fail("bad " + std::string(what) + " " + quote(t) + " (expected a finite number)");
    return v;
}

void TextScanner::check_count(std::int64_t count, std::int64_t tokens_each, std::string_view what) const {
    const auto left = static_cast<std::int64_t>(text_.size() - pos_);
    if (count < 0) fail("negative " + std::string(what) + " count " + std::to_string(count));
    if (tokens_each > 0 && count > (left + 1) / (2 * tokens_each))
        fail(std::string(what) + " count " + std::to_string(count) + " exceeds what the rest of the file (" +
             std::to_string(left) + " bytes) can hold");
}

}  // namespace dualhex::audit::detail
