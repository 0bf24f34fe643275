#include "classification.hpp"

#include "commands.hpp"

#if __has_include("dualhex/grid/configurations.hpp")
#include "dualhex/grid/configurations.hpp"
#define DUALHEX_APP_HAVE_CONFIGURATIONS 1
#endif

namespace dualhex::app {

Classification compute_classification() {
#ifdef DUALHEX_APP_HAVE_CONFIGURATIONS
    const ConfigurationSpace full(SymmetryGroup::Full);
    const ConfigurationSpace rotations(SymmetryGroup::Rotations);
    Classification c;
    for (const auto& cls : full.classes()) {
        c.classes.push_back({static_cast<int>(cls.representative), cls.size, cls.fine});
        c.configurations += cls.size;
    }
    c.classes_full_group = static_cast<int>(full.classes().size());
    c.classes_rotations = static_cast<int>(rotations.classes().size());
    c.nontrivial_classes = full.transition_count();
    return c;
#else
    throw NotYetAvailable(
        "the configuration classification (grid/include/dualhex/grid/configurations.hpp) is not in the grid layer yet");
#endif
}

}  // namespace dualhex::app
