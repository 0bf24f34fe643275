#pragma once
// Loading the element library that install() places, and its lattice unit. install.hpp
// only forward-declares ElementLibrary, so a pipeline that installs needs this header, not
// the whole schemes/element_library.hpp.
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
