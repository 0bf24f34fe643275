#include "classification.hpp"

#include "commands.hpp"

#include "dualhex/grid/configurations.hpp"

namespace dualhex::app {

Classification compute_classification() {
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
}

}  // namespace dualhex::app
