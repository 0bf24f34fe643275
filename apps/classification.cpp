#include "classification.hpp"

#include "commands.hpp"

namespace dualhex::app {

Classification compute_classification() {
    throw NotYetAvailable(
        "the configuration classification (grid/include/dualhex/grid/configurations.hpp) is not in the grid layer yet");
}

}  // namespace dualhex::app
