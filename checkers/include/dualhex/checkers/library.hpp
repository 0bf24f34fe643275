#pragma once
// Loading an ElementLibrary without including schemes/element_library.hpp.
//
// Why: schemes/element_check.hpp and grid/leaf.hpp both define dualhex::LeafBox, so no
// translation unit can include both the element library and the grid. Code that installs
// into a LeafGrid (install.hpp) therefore only needs a forward-declared ElementLibrary,
// and gets one from here.
#include <cstdint>
#include <filesystem>
#include <memory>

namespace dualhex {

class ElementLibrary;

/// ElementLibrary::load(directory) (strict: throws SchemeFormatError naming the file).
[[nodiscard]] std::shared_ptr<const ElementLibrary> load_element_library(const std::filesystem::path& directory);
/// ElementLibrary::load_default().
[[nodiscard]] std::shared_ptr<const ElementLibrary> load_default_element_library();
/// The lattice unit U the checkers use for a library: the lcm of its elements' `leaf`
/// resolutions, doubled if odd (fine leaves are U/2); 2 for an empty library.
[[nodiscard]] std::int64_t lattice_unit(const ElementLibrary& library);

}  // namespace dualhex
