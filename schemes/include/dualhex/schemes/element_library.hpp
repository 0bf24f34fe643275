#pragma once
// The element library: every `*.element` file of a directory, parsed and validated.
//
// The shipped elements (schemes/elements/) are compiled into the library
// (embedded_elements.hpp): load_default() uses them unless DUALHEX_ELEMENTS names a
// directory, so a program built against an installed or relocated dualhex never needs to
// find a directory. load(directory) reads a user library.
//
// Where the files are found on disk (default_elements_directory: `dualhex element`, the
// directory() of the embedded library, tools that copy the files), first match wins:
//   1. the environment variable DUALHEX_ELEMENTS (a directory), if set and non-empty;
//   2. <directory of the running executable>/../share/dualhex/elements (an installed
//      tree: `install(DIRECTORY ...)` puts them in ${CMAKE_INSTALL_DATADIR}/dualhex/elements);
//   3. <an ancestor of the binary holding this code>/share/dualhex/elements (up to 6 levels
//      up: a shared module such as the installed Python extension);
//   4. the source tree's schemes/elements (compile-time path, for the build tree).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/schemes/element.hpp"
#include "dualhex/schemes/element_check.hpp"
#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/cube_symmetry.hpp"

namespace dualhex {

/// A loaded element: the file's data, its complex, and its check report.
struct Element {
    std::string name;
    std::filesystem::path file;
    ElementData data;
    CellComplex complex;
    ElementCheckReport check;

    [[nodiscard]] std::int64_t leaf() const { return data.leaf; }
    [[nodiscard]] bool valid() const { return check.ok(); }
    [[nodiscard]] std::vector<std::string> cell_labels() const;
};

/// Parses and checks one file (never throws for an invalid element; throws
/// SchemeFormatError for a malformed file).
[[nodiscard]] Element load_element(const std::filesystem::path& file);

/// One file of a directory scan: either an element (valid or not) or a parse error.
struct ElementScanEntry {
    std::filesystem::path file;
    std::optional<Element> element;
    std::string error;  // non-empty iff the file did not parse
};

/// See the header comment. Throws SchemeFormatError if none of the places exists.
[[nodiscard]] std::filesystem::path default_elements_directory();
/// default_elements_directory(), or an empty path if none of the places exists.
[[nodiscard]] std::filesystem::path find_elements_directory();
/// The pseudo-directory the embedded elements' `file` names lie in ("<embedded>/F.element").
inline constexpr const char* kEmbeddedElementsDirectory = "<embedded>";
/// The compile-time source-tree directory (may not exist in an installed tree).
[[nodiscard]] std::filesystem::path source_elements_directory();

/// Every *.element of `directory`, sorted by file name, errors kept (for listings).
[[nodiscard]] std::vector<ElementScanEntry> scan_elements(const std::filesystem::path& directory);

/// A point image of the leaf: the box that `instance(..., symmetry, translation)` fills,
/// i.e. the image of [0, leaf]^3 under p -> symmetry.apply(p) + translation.
[[nodiscard]] ElementBox placed_leaf_box(std::int64_t leaf, const CubeSymmetry& symmetry, const LatticePoint& translation);

class ElementLibrary {
public:
    /// Loads every *.element of `directory` (strict): a file that does not parse, an
    /// element that fails check_element, a name that differs from the file stem, or a
    /// duplicate name is a SchemeFormatError naming the file.
    [[nodiscard]] static ElementLibrary load(const std::filesystem::path& directory);
    /// The shipped elements compiled into the library, checked as strictly as load();
    /// directory() is find_elements_directory() (possibly empty).
    [[nodiscard]] static ElementLibrary load_embedded();
    /// load(DUALHEX_ELEMENTS) if that variable is set and non-empty, else load_embedded().
    [[nodiscard]] static ElementLibrary load_default();

    [[nodiscard]] const std::filesystem::path& directory() const { return directory_; }
    [[nodiscard]] const std::vector<Element>& elements() const { return elements_; }
    [[nodiscard]] std::vector<std::string> names() const;
    [[nodiscard]] const Element* find(const std::string& name) const;
    /// Throws std::out_of_range naming the known elements.
    [[nodiscard]] const Element& at(const std::string& name) const;

    /// The element placed by a cube symmetry about its application point (the origin)
    /// followed by a translation (topology `transform`): ids are unchanged, cells stay
    /// outward-oriented. The image fills placed_leaf_box(leaf, symmetry, translation).
    [[nodiscard]] CellComplex instance(const std::string& name, const CubeSymmetry& symmetry,
                                       const LatticePoint& translation = {}) const;

private:
    /// Appends `e` unless it is invalid, misnamed (name != file stem) or a duplicate
    /// (SchemeFormatError naming its file).
    void add_strict(Element e);
    void sort_by_name();

    std::filesystem::path directory_;
    std::vector<Element> elements_;  // sorted by name
};

}  // namespace dualhex
