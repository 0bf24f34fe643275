// The install, verify and dual stages (install_stage.hpp).
#include "dualhex/mesher/install_stage.hpp"

#include <stdexcept>
#include <string>

#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex::mesher {

InstallResult install_schemes(const LeafGrid& grid, Balance balance) {
    const auto library = load_default_element_library();
    const InstallOptions options{.outside_root = OutsideRoot::Coarse, .balance = balance};
    return balance == Balance::Strong ? install(grid, StrongRule(), *library, options)
                                      : install(grid, WeakRule(), *library, options);
}

InstallVerification require_verified(const InstallResult& installed) {
    InstallVerification verification = verify_installation(installed);
    if (!verification.ok()) throw std::runtime_error("installation does not verify: " + verification.summary());
    return verification;
}

std::int64_t root_extent(const InstallResult& installed) { return installed.unit << installed.max_level; }

ClippedDual root_clipped_dual(const InstallResult& installed) {
    const std::int64_t extent = root_extent(installed);
    const Incidence incidence(installed.complex);
    ClippedDual dual = clipped_dual(installed.complex, incidence, {0, 0, 0}, {extent, extent, extent});
    if (!dual.all_cubes())
        throw std::runtime_error("clipped dual: " + std::to_string(dual.errors.size()) +
                                 " vertices without a cube, e.g. " + dual.errors.front().message);
    return dual;
}

}  // namespace dualhex::mesher
