// dualhex atlas -o DIR: a static site with a 3D view of every element, strong transition,
// weak class and crossing variant (atlas/, atlas/site/).
#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "dualhex/atlas/site.hpp"

namespace dualhex::app {
namespace {

struct AtlasOptions {
    std::string output;
    bool force = false, json = false;
};

void run_atlas(const AtlasOptions& o) {
    try {
        atlas::check_output_directory(o.output, o.force);  // refuse before the work
    } catch (const atlas::SiteError& e) {
        throw UsageError(e.what());
    }
    const ElementLibrary library = ElementLibrary::load_default();
    const auto pages = atlas::all_pages(library);
    nlohmann::json summary;
    try {
        summary = atlas::write_site(pages, o.output, o.force);
    } catch (const atlas::SiteError& e) {
        std::cerr << "error: " << e.what() << '\n';
        throw Exit{kInputError};
    }
    std::map<std::string, int> kinds;
    for (const auto& p : summary["pages"]) ++kinds[p["kind"].get<std::string>()];
    if (o.json) {
        summary["directory"] = o.output;
        summary["index"] = (std::filesystem::path(o.output) / "index.html").string();
        print_json(summary);
        return;
    }
    std::cout << "wrote " << summary["pages"].size() << " pages to " << o.output << ":";
    for (const auto& [kind, n] : kinds) std::cout << ' ' << kind << '=' << n;
    std::cout << "\nopen " << (std::filesystem::path(o.output) / "index.html").string() << '\n';
}

}  // namespace

void register_atlas(CLI::App& app) {
    auto opts = std::make_shared<AtlasOptions>();
    auto* sub = app.add_subcommand("atlas", "Write a static 3D atlas (three.js) of the elements, transitions and variants");
    sub->add_option("-o,--output", opts->output, "Output directory (must not exist or be empty, unless --force)")->required();
    sub->add_flag("--force", opts->force, "Write into a non-empty directory, overwriting the atlas's files");
    add_json_flag(*sub, opts->json);
    sub->callback([opts] { run_atlas(*opts); });
}

}  // namespace dualhex::app
