#include "commands.hpp"

#include <iostream>

#include "dualhex/grid/input_error.hpp"

namespace dualhex::app {

CLI::Option* add_json_flag(CLI::App& sub, bool& json) {
    return sub.add_flag("--json", json, "Machine-readable JSON on stdout (and nothing else on stdout)");
}

void add_output_options(CLI::App& sub, std::string& output, bool& force) {
    sub.add_option("-o,--output", output, "Output file")->required();
    sub.add_flag("--force", force, "Overwrite the output file if it exists");
}

void check_output(const std::filesystem::path& path, bool force) {
    std::error_code ec;
    if (!force && std::filesystem::exists(path, ec))
        throw UsageError("output file '" + path.string() + "' exists; use --force to overwrite it");
}

std::ofstream open_output(const std::filesystem::path& path, bool force) {
    check_output(path, force);
    std::ofstream out(path, std::ios::out | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + path.string() + "' for writing");
    return out;
}

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << '\n'; }

}  // namespace dualhex::app

namespace dualhex::app {

std::optional<std::string> input_error_message(const std::exception& e) {
    if (const auto* ie = dynamic_cast<const dualhex::InputError*>(&e)) return std::string(ie->what());
    return std::nullopt;
}

}  // namespace dualhex::app
