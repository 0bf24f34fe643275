// dualhex certify --out DIR: writes the certificates of the element library and of the 256
// configurations under the strong rule (format and checker: proofs/README.md). The
// certificates are untrusted output; `dualhex-proof-checker DIR/manifest` re-checks them.
#include <iostream>

#include "commands.hpp"
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/signature_rule.hpp"

namespace dualhex::app {

void register_certify(CLI::App& app) {
    auto* sub = app.add_subcommand("certify",
                                   "Write certificates (elements + the 256 strong-rule configurations) for the "
                                   "independent checker dualhex-proof-checker");
    struct Options {
        std::string out, elements;
        bool force = false, json = false;
    };
    auto opt = std::make_shared<Options>();
    sub->add_option("--out", opt->out, "Directory to write the certificates and the manifest into")->required();
    sub->add_option("--elements", opt->elements, "Element directory (default: the element library's default)");
    sub->add_flag("--force", opt->force, "Overwrite an existing manifest in DIR");
    add_json_flag(*sub, opt->json);
    sub->callback([opt] {
        const std::filesystem::path dir = opt->out;
        check_output(dir / "manifest", opt->force);
        const ElementLibrary library =
            opt->elements.empty() ? ElementLibrary::load_default() : ElementLibrary::load(opt->elements);
        const StrongRule rule;
        const CertifyResult result = certify_library(library, rule, dir);
        if (opt->json) {
            nlohmann::json files = nlohmann::json::array();
            for (const ManifestEntry& e : result.files)
                files.push_back({{"file", e.file}, {"certificates", e.certificates}, {"kind", to_string(e.kind)},
                                 {"fnv1a64", e.hash}});
            print_json({{"directory", dir.string()}, {"manifest", (dir / "manifest").string()},
                        {"certificates", result.certificates}, {"bytes", result.bytes}, {"files", files}});
            return;
        }
        for (const ManifestEntry& e : result.files)
            std::cout << (dir / e.file).string() << ": " << e.certificates << ' ' << to_string(e.kind)
                      << " certificates, fnv1a64 " << e.hash << '\n';
        std::cout << "wrote " << result.certificates << " certificates (" << result.bytes << " bytes) and "
                  << (dir / "manifest").string() << "\nre-check with: dualhex-proof-checker "
                  << (dir / "manifest").string() << '\n';
    });
}

}  // namespace dualhex::app
