// The element files compiled into the schemes library (schemes/embedded_elements.hpp) are
// the source tree's files, and load_default() uses them unless DUALHEX_ELEMENTS is set.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/embedded_elements.hpp"

namespace fs = std::filesystem;
using namespace dualhex;

namespace {
fs::path source_elements() { return fs::path(DUALHEX_SOURCE_DIR) / "schemes" / "elements"; }

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}
}  // namespace

TEST(SchemesEmbedded, TheEmbeddedTextIsTheSourceFiles) {
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(source_elements()))
        files += entry.path().extension() == ".element" ? 1 : 0;
    ASSERT_EQ(embedded_element_files().size(), files);
    for (const EmbeddedElementFile& f : embedded_element_files())
        EXPECT_EQ(f.text, read_text(source_elements() / f.file_name)) << f.file_name;
}

TEST(SchemesEmbedded, TheEmbeddedLibraryEqualsTheDirectory) {
    const ElementLibrary embedded = ElementLibrary::load_embedded();
    const ElementLibrary files = ElementLibrary::load(source_elements());
    ASSERT_EQ(embedded.names(), files.names());
    EXPECT_EQ(embedded.names().size(), 13U);
    for (const Element& e : embedded.elements()) {
        const Element& f = files.at(e.name);
        EXPECT_EQ(e.data, f.data) << e.name;
        EXPECT_TRUE(e.valid()) << e.name;
        EXPECT_EQ(e.file, fs::path(kEmbeddedElementsDirectory) / (e.name + ".element"));
        EXPECT_EQ(e.file.filename(), f.file.filename());  // what certificates record
    }
}

TEST(SchemesEmbedded, LoadDefaultIsEmbeddedUnlessTheVariableIsSet) {
    ::unsetenv("DUALHEX_ELEMENTS");
    const ElementLibrary lib = ElementLibrary::load_default();
    ASSERT_FALSE(lib.elements().empty());
    EXPECT_EQ(lib.elements().front().file.parent_path(), fs::path(kEmbeddedElementsDirectory));
    const fs::path dir = fs::temp_directory_path() / "dualhex_embedded_env";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(source_elements() / "F.element", dir / "F.element");
    ::setenv("DUALHEX_ELEMENTS", dir.c_str(), 1);
    const ElementLibrary user = ElementLibrary::load_default();
    ::unsetenv("DUALHEX_ELEMENTS");
    ASSERT_EQ(user.names(), std::vector<std::string>{"F"});
    EXPECT_EQ(user.elements().front().file, dir / "F.element");
    EXPECT_EQ(user.directory(), dir);
    fs::remove_all(dir);
}
