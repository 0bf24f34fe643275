#include "dualhex/schemes/element_library.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "dualhex/schemes/embedded_elements.hpp"
#include "dualhex/topology/transform.hpp"

#ifndef DUALHEX_ELEMENTS_SOURCE_DIR
#define DUALHEX_ELEMENTS_SOURCE_DIR ""
#endif
#ifndef DUALHEX_INSTALL_DATADIR
#define DUALHEX_INSTALL_DATADIR "share"
#endif

namespace dualhex {

namespace fs = std::filesystem;

std::vector<std::string> Element::cell_labels() const {
    std::vector<std::string> labels;
    for (const auto& c : data.cells) labels.push_back(c.label);
    return labels;
}

namespace {
Element make_element(fs::path file, ElementData data) {
    Element e;
    e.file = std::move(file);
    e.data = std::move(data);
    e.name = e.data.name;
    e.complex = to_complex(e.data);
    e.check = check_element(e.complex, ElementBox{{}, e.data.leaf}, e.cell_labels());
    return e;
}
}  // namespace

Element load_element(const fs::path& file) { return make_element(file, read_element_file(file)); }

fs::path source_elements_directory() { return fs::path(DUALHEX_ELEMENTS_SOURCE_DIR); }

namespace {
// The binary holding this code may be a shared module (the Python extension, installed at
// <prefix>/lib/python3.X/.../dualhex/): the nearest of its ancestors with the installed
// element directory.
fs::path installed_beside_this_code() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&default_elements_directory), &info) == 0 || !info.dli_fname) return {};
    std::error_code ec;
    fs::path dir = fs::weakly_canonical(fs::path(info.dli_fname), ec).parent_path();
    if (ec) return {};
    for (int up = 0; up < 6 && !dir.empty(); ++up, dir = dir.parent_path()) {
        const fs::path candidate = dir / DUALHEX_INSTALL_DATADIR / "dualhex" / "elements";
        if (fs::is_directory(candidate, ec)) return candidate;  // (ec: missing, keep looking)
        if (dir == dir.root_path()) break;
    }
    return {};
}
}  // namespace

fs::path find_elements_directory() {
    try {
        return default_elements_directory();
    } catch (const SchemeFormatError&) {
        return {};
    }
}

fs::path default_elements_directory() {
    std::error_code ec;
    if (const char* env = std::getenv("DUALHEX_ELEMENTS"); env && *env) {
        fs::path p(env);
        if (!fs::is_directory(p, ec))
            throw SchemeFormatError(p.string(), 0, "DUALHEX_ELEMENTS is not a directory");
        return p;
    }
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path() / ".." / DUALHEX_INSTALL_DATADIR / "dualhex" / "elements";
        if (fs::is_directory(installed, ec)) return installed.lexically_normal();
    }
    if (const fs::path beside = installed_beside_this_code(); !beside.empty()) return beside;
    const fs::path src = source_elements_directory();
    if (!src.empty() && fs::is_directory(src, ec)) return src;
    throw SchemeFormatError("", 0,
                            "no element directory found (set DUALHEX_ELEMENTS, or install share/dualhex/elements)");
}

namespace {
std::vector<fs::path> element_files(const fs::path& directory) {
    std::error_code ec;
    if (!fs::is_directory(directory, ec)) throw SchemeFormatError(directory.string(), 0, "not a directory");
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.is_regular_file() && entry.path().extension() == ".element") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}
}  // namespace

std::vector<ElementScanEntry> scan_elements(const fs::path& directory) {
    std::vector<ElementScanEntry> out;
    for (const auto& f : element_files(directory)) {
        ElementScanEntry s;
        s.file = f;
        try {
            s.element = load_element(f);
        } catch (const SchemeFormatError& e) {
            s.error = e.what();
        }
        out.push_back(std::move(s));
    }
    return out;
}

ElementBox placed_leaf_box(std::int64_t leaf, const CubeSymmetry& symmetry, const LatticePoint& translation) {
    const LatticePoint far = symmetry.apply({leaf, leaf, leaf});
    LatticePoint lo = translation;
    for (int a = 0; a < 3; ++a) lo[a] += std::min<std::int64_t>(0, far[a]);
    return {lo, leaf};
}

ElementLibrary ElementLibrary::load(const fs::path& directory) {
    ElementLibrary lib;
    lib.directory_ = directory;
    for (const auto& file : element_files(directory))
        lib.add_strict(load_element(file));  // a malformed file throws its own file:line error
    lib.sort_by_name();
    return lib;
}

ElementLibrary ElementLibrary::load_embedded() {
    ElementLibrary lib;
    lib.directory_ = find_elements_directory();
    for (const auto& f : embedded_element_files()) {
        const fs::path file = fs::path(kEmbeddedElementsDirectory) / f.file_name;
        lib.add_strict(make_element(file, parse_element_string(f.text, file.string())));
    }
    lib.sort_by_name();
    return lib;
}

ElementLibrary ElementLibrary::load_default() {
    if (const char* env = std::getenv("DUALHEX_ELEMENTS"); env && *env) return load(default_elements_directory());
    return load_embedded();
}

void ElementLibrary::sort_by_name() {
    std::sort(elements_.begin(), elements_.end(), [](const Element& a, const Element& b) { return a.name < b.name; });
}

void ElementLibrary::add_strict(Element e) {
    const std::string file = e.file.string();
    if (!e.valid()) {
        std::ostringstream os;
        os << "element '" << e.name << "' is invalid: ";
        e.check.print(os, 10);
        throw SchemeFormatError(file, 0, os.str());
    }
    const std::string stem = e.file.stem().string();
    if (e.name != stem)
        throw SchemeFormatError(file, 0, "element name '" + e.name + "' differs from the file name '" + stem + "'");
    if (find(e.name)) throw SchemeFormatError(file, 0, "duplicate element name '" + e.name + "'");
    elements_.push_back(std::move(e));
}

std::vector<std::string> ElementLibrary::names() const {
    std::vector<std::string> n;
    for (const auto& e : elements_) n.push_back(e.name);
    return n;
}

const Element* ElementLibrary::find(const std::string& name) const {
    for (const auto& e : elements_)
        if (e.name == name) return &e;
    return nullptr;
}

const Element& ElementLibrary::at(const std::string& name) const {
    if (const auto* e = find(name)) return *e;
    std::string known;
    for (const auto& n : names()) known += (known.empty() ? "" : ", ") + n;
    throw std::out_of_range("unknown element '" + name + "' (known: " + known + ")");
}

CellComplex ElementLibrary::instance(const std::string& name, const CubeSymmetry& symmetry,
                                     const LatticePoint& translation) const {
    return transform(at(name).complex, symmetry, translation);
}

}  // namespace dualhex
