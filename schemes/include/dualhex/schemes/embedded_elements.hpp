#pragma once
// The shipped element files (schemes/elements/*.element), compiled into the library at
// build time (cmake/embed_elements.cmake), so ElementLibrary::load_default() works in any
// installed or relocated tree without finding a directory.
#include <string>
#include <vector>

namespace dualhex {

struct EmbeddedElementFile {
    std::string file_name;  ///< e.g. "F.element"
    std::string text;       ///< the file's exact content
};

/// Sorted by file name (the order of the source directory's listing).
[[nodiscard]] const std::vector<EmbeddedElementFile>& embedded_element_files();

}  // namespace dualhex
