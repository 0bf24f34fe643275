#include "commands.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>

#include "dualhex/grid/input_error.hpp"

namespace dualhex::app {

namespace fs = std::filesystem;

CLI::Option* add_json_flag(CLI::App& sub, bool& json) {
    return sub.add_flag("--json", json, "Machine-readable JSON on stdout (and nothing else on stdout)");
}

void add_output_options(CLI::App& sub, std::string& output, bool& force) {
    sub.add_option("-o,--output", output, "Output file")->required();
    sub.add_flag("--force", force, "Overwrite the output file if it exists");
}

namespace {

[[noreturn]] void unwritable(const fs::path& path, const std::string& why) {
    throw dualhex::InputError(path.string(), 0, "cannot write output: " + why);
}

// The nearest existing ancestor of a path that does not exist ("." for a relative name).
fs::path existing_ancestor(const fs::path& path) {
    fs::path dir = path.parent_path();
    std::error_code ec;
    while (!dir.empty() && !fs::exists(dir, ec)) dir = dir.parent_path();
    return dir.empty() ? fs::path(".") : dir;
}

// Creates and removes a scratch file in `dir`: the one test that also sees read-only file
// systems and permissions as root does.
void probe_directory(const fs::path& dir, const fs::path& for_path) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) unwritable(for_path, "'" + dir.string() + "' is not a directory");
    const fs::path probe = dir / (".dualhex-write-probe-" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) unwritable(for_path, "cannot create files in '" + dir.string() + "': " + std::strerror(errno));
    ::close(fd);
    ::unlink(probe.c_str());
}

}  // namespace

void check_output(const fs::path& path, bool force) {
    std::error_code ec;
    const auto status = fs::symlink_status(path, ec);
    if (!fs::exists(status)) {  // the writers create no directories: the parent must exist
        const fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
        if (!fs::exists(parent, ec)) unwritable(path, "directory '" + parent.string() + "' does not exist");
        probe_directory(parent, path);
        return;
    }
    if (fs::is_directory(fs::status(path, ec))) unwritable(path, "it is a directory");
    if (!force) throw UsageError("output file '" + path.string() + "' exists; use --force to overwrite it");
    // Opening without O_TRUNC changes nothing; O_NONBLOCK keeps a FIFO from blocking.
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) unwritable(path, std::strerror(errno));
    ::close(fd);
}

void check_output_directory(const fs::path& dir, bool force) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) {
        probe_directory(existing_ancestor(dir), dir);  // certify creates the missing directories
        return;
    }
    if (!fs::is_directory(dir, ec)) unwritable(dir, "it exists and is not a directory");
    if (!force && !fs::is_empty(dir, ec))
        throw UsageError("output directory '" + dir.string() + "' is not empty; use --force to overwrite files in it");
    probe_directory(dir, dir);
}

std::ofstream open_output(const fs::path& path, bool force) {
    check_output(path, force);
    std::ofstream out(path, std::ios::out | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + path.string() + "' for writing");
    return out;
}

std::string utf8_escaped(const std::string& text) {
    std::string out;
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = byte(i);
        // Length of the sequence c starts and the smallest code point it may encode.
        const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        bool valid = n > 0 && i + n <= text.size();
        std::uint32_t cp = n == 1 ? c : n == 2 ? c & 0x1f : n == 3 ? c & 0x0f : c & 0x07;
        for (std::size_t k = 1; valid && k < n; ++k) {
            valid = (byte(i + k) >> 6) == 2;
            cp = (cp << 6) | (byte(i + k) & 0x3f);
        }
        static constexpr std::uint32_t kMin[5] = {0, 0, 0x80, 0x800, 0x10000};
        valid = valid && cp >= kMin[n] && cp <= 0x10ffff && !(cp >= 0xd800 && cp <= 0xdfff);  // no overlong, no surrogates
        if (valid) {
            out.append(text, i, n);
            i += n;
        } else {
            static const char* hex = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
            ++i;
        }
    }
    return out;
}

namespace {
nlohmann::json utf8_safe(const nlohmann::json& j) {
    if (j.is_string()) return utf8_escaped(j.get_ref<const std::string&>());
    if (j.is_array()) {
        nlohmann::json out = nlohmann::json::array();
        for (const auto& v : j) out.push_back(utf8_safe(v));
        return out;
    }
    if (j.is_object()) {
        nlohmann::json out = nlohmann::json::object();
        for (const auto& [k, v] : j.items()) out[utf8_escaped(k)] = utf8_safe(v);
        return out;
    }
    return j;
}
}  // namespace

void print_json(const nlohmann::json& j) { std::cout << utf8_safe(j).dump(2) << '\n'; }

}  // namespace dualhex::app

namespace dualhex::app {

std::optional<std::string> input_error_message(const std::exception& e) {
    if (const auto* ie = dynamic_cast<const dualhex::InputError*>(&e)) return std::string(ie->what());
    return std::nullopt;
}

}  // namespace dualhex::app
