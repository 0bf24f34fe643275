// dualhex certify --out DIR: writes the certificates of the element library, the 256
// configurations under the strong rule (DIR), the 487 weakly balanced ones under the weak rule
// (DIR/weak), the 14 crossing variants (DIR/variants), the compositional windows (DIR/windows)
// the root-boundary half windows (DIR/boundary), the eight four-level weak grids
// (DIR/weak_spread), the weak stars (DIR/weak_stars), the witness stars of the corner pair
// (DIR/weak_corner_stars) and the weak root-surface stars (DIR/weak_root_stars), each
// directory with its manifest; with --near-root-stars also the
// weak stars near the root surface under Coarse (DIR/weak_near_root_stars, not shipped)
// (format and checker: proofs/README.md). The certificates are untrusted output;
// `dualhex-proof-checker DIR/manifest` (and DIR/weak/manifest, DIR/variants/manifest)
// re-checks them. Without --force DIR must not exist or be empty.
#include <iostream>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex::app {

void register_certify(CLI::App& app) {
    auto* sub = app.add_subcommand("certify",
                                   "Write certificates (elements, the 256 strong and 487 weak configurations, the 14 "
                                   "crossing variants, the compositional and root-boundary windows, the four-level weak grids, the "
                                   "weak stars) for the "
                                   "independent checker dualhex-proof-checker");
    struct Options {
        std::string out, elements;
        bool force = false, json = false, no_progress = false, near_root_stars = false;
    };
    auto opt = std::make_shared<Options>();
    sub->add_option("--out", opt->out, "Directory to write the certificates and the manifest into")->required();
    sub->add_option("--elements", opt->elements, "Element directory (default: the element library's default)");
    sub->add_flag("--force", opt->force, "Write into DIR even if it is not empty (overwriting certificates and manifests in it)");
    sub->add_flag("--near-root-stars", opt->near_root_stars,
                  "Also certify the weak stars near the root surface under Coarse into DIR/weak_near_root_stars "
                  "(1,104,872 stars in 20,365 certificates, about 70 MB; minutes of CPU and several GB of memory)");
    add_json_flag(*sub, opt->json);
    add_no_progress_flag(*sub, opt->no_progress);
    sub->callback([opt] {
        const std::filesystem::path dir = opt->out;
        // Before any work: nothing in DIR may be overwritten without --force (the files it
        // writes are named by their contents' ranges, so none can be checked one by one).
        check_output_directory(dir, opt->force);
        const ElementLibrary library =
            opt->elements.empty() ? ElementLibrary::load_default() : ElementLibrary::load(opt->elements);
        ProgressBar bar = ProgressBar::for_stderr(opt->json, opt->no_progress);
        const CertifyResult result = certify_library(library, dir, bar.callback(), opt->near_root_stars);
        bar.finish("certify: " + with_commas(result.certificates()) + " certificates written to " + dir.string());
        if (opt->json) {
            nlohmann::json sets = nlohmann::json::array();
            for (const CertificateSet& set : result.sets) {
                nlohmann::json files = nlohmann::json::array();
                for (const ManifestEntry& e : set.files)
                    files.push_back({{"file", e.file}, {"certificates", e.certificates}, {"kind", to_string(e.kind)},
                                     {"fnv1a64", e.hash}});
                sets.push_back({{"directory", set.directory.string()}, {"manifest", (set.directory / "manifest").string()},
                                {"certificates", set.certificates}, {"bytes", set.bytes}, {"covers", set.covers},
                                {"files", files}});
            }
            print_json({{"directory", dir.string()}, {"manifest", (dir / "manifest").string()},
                        {"certificates", result.certificates()}, {"bytes", result.bytes()}, {"sets", sets}});
            return;
        }
        for (const CertificateSet& set : result.sets) {
            for (const ManifestEntry& e : set.files)
                std::cout << (set.directory / e.file).string() << ": " << e.certificates << ' ' << to_string(e.kind)
                          << " certificates, fnv1a64 " << e.hash << '\n';
            std::cout << (set.directory / "manifest").string() << ": " << set.certificates << " certificates ("
                      << set.bytes << " bytes), covering labels 0.." << set.covers - 1 << '\n';
        }
        std::cout << "wrote " << result.certificates() << " certificates (" << result.bytes()
                  << " bytes); re-check each manifest with: dualhex-proof-checker MANIFEST\n";
    });
}

}  // namespace dualhex::app
