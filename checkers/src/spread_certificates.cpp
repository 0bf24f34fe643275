// Certificates of the eight four-level grids (compositional_weak.hpp, spread_three_grid):
// each installed with the weak rule (outside root coarse), checked by dualhex, and written
// as one `installation` certificate over the root box, covering its corner's label.
#include <stdexcept>

#include "dualhex/checkers/compositional_weak.hpp"
#include "dualhex/install/install.hpp"
#include "dualhex/install/verify_installation.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex {

CertificateSet certify_spread_grids(const ElementLibrary& library, const std::filesystem::path& dir) {
    CertificateSet set(dir, 8);
    std::string text;
    for (int corner = 0; corner < 8; ++corner) {
        const InstallResult installed = install(spread_three_grid(2, corner), WeakRule(), library);
        const InstallVerification v = verify_installation(installed);
        if (!v.ok()) throw std::runtime_error("certify_spread_grids: corner " + std::to_string(corner) + " fails: " + v.summary());
        const std::int64_t extent = installed.unit << installed.max_level;
        CertificateSpec spec;
        spec.name = "spread-" + std::to_string(corner);
        spec.kind = CertificateKind::Installation;
        spec.domain = CertificateDomain::box({0, 0, 0}, {extent, extent, extent});
        spec.comments = {"spread_three_grid(2, " + std::to_string(corner) +
                             "): leaves of levels 2..5 at the root's centre, the deep side at corner " +
                             std::to_string(corner) + " (proofs/README.md, \"Weak balance\", W3)",
                         "installed with the weak rule, outside root coarse"};
        spec.covers = {corner};
        text += certificate_to_string(installed.complex, spec);
    }
    set.add("spread-0-7.cert", text, 8, CertificateKind::Installation);
    set.write_manifest();
    return set;
}

}  // namespace dualhex
