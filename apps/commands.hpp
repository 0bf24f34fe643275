#pragma once
// The `dualhex` command line: one file per subcommand, each exposing a register_<name>
// function that adds its CLI11 subcommand to the app. main.cpp only builds the app,
// registers the subcommands and maps outcomes to exit codes.
//
// Exit codes (documented in README.md):
//   0 success, 1 a verification/check failed, 2 usage error (bad arguments, or an output
//   file exists and --force was not given), 3 input error (malformed input file),
//   4 internal error (any other exception).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

namespace dualhex::app {

enum ExitCode : int { kOk = 0, kCheckFailed = 1, kUsage = 2, kInputError = 3, kInternal = 4 };

/// Subcommand callbacks end by throwing this when they want a non-zero exit code
/// (main.cpp catches it). Printing is the command's job; this carries only the code.
struct Exit {
    int code;
};

/// A usage problem detected by a command after parsing (exit code 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A feature whose underlying library part does not exist yet (exit code 4).
struct NotYetAvailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void register_classify(CLI::App& app);
void register_grid(CLI::App& app);
void register_verify(CLI::App& app);
void register_element(CLI::App& app);
void register_table(CLI::App& app);
void register_install(CLI::App& app);
void register_certify(CLI::App& app);
void register_variants(CLI::App& app);
void register_mesh(CLI::App& app);
void register_audit(CLI::App& app);
void register_atlas(CLI::App& app);

// --- shared helpers (commands.cpp) ---

/// Adds the `--json` flag every subcommand has.
CLI::Option* add_json_flag(CLI::App& sub, bool& json);

/// Adds `-o,--output FILE` (required) and `--force` to a command that writes a file.
void add_output_options(CLI::App& sub, std::string& output, bool& force);

/// Call before the work, so a refused output costs nothing. Throws UsageError (exit 2) if
/// `path` exists and not `force`; InputError (exit 3, "path: why") if it cannot be
/// written: an existing directory, an existing file that cannot be opened for writing,
/// or (not existing) a parent directory that does not exist or cannot be written. Probes by opening the file
/// without truncating it, or by creating and removing a scratch file beside it.
void check_output(const std::filesystem::path& path, bool force);

/// The same for an output directory that a command fills with files it names itself
/// (certify): without `force` it must not exist or be empty (nothing in it may be
/// overwritten); it must be (or be creatable as) a writable directory.
void check_output_directory(const std::filesystem::path& dir, bool force);

/// `text` with every byte that is not part of valid UTF-8 written as "\xNN": what JSON
/// output does with file names (which may be any bytes) instead of failing.
std::string utf8_escaped(const std::string& text);

/// Opens `path` for writing. Refuses (UsageError, exit 2) to overwrite an existing file
/// unless `force`; throws std::runtime_error if the file cannot be opened.
std::ofstream open_output(const std::filesystem::path& path, bool force);

/// If `e` is a dualhex::InputError (malformed input file), "<file>:<line>: <message>".
std::optional<std::string> input_error_message(const std::exception& e);

/// Prints `j` on stdout (pretty, 2 spaces) followed by a newline; strings (and keys) that
/// are not valid UTF-8 are printed utf8_escaped, so the output never fails.
void print_json(const nlohmann::json& j);

}  // namespace dualhex::app
