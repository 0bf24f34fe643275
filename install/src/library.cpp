// Loading element libraries for installation (library.hpp).
#include "dualhex/install/library.hpp"

#include "dualhex/install/element_templates.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex {

std::shared_ptr<const ElementLibrary> load_element_library(const std::filesystem::path& directory) {
    return std::make_shared<const ElementLibrary>(ElementLibrary::load(directory));
}

std::shared_ptr<const ElementLibrary> load_default_element_library() {
    return std::make_shared<const ElementLibrary>(ElementLibrary::load_default());
}

std::int64_t lattice_unit(const ElementLibrary& library) { return detail::common_unit(library); }

}  // namespace dualhex
