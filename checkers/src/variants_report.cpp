#include "dualhex/checkers/variants_report.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <fstream>
#include <functional>
#include <iomanip>
#include <ostream>
#include <random>
#include <set>
#include <sstream>
#include <unordered_map>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/schemes/element_check.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/histograms.hpp"

namespace dualhex::variants {
namespace fs = std::filesystem;

namespace {


// A fresh directory under the system temp directory.
fs::path fresh_directory() {
    static std::atomic<unsigned> counter{0};
    std::random_device rd;
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path p = fs::temp_directory_path() /
                           ("dualhex-variants-" + std::to_string(rd()) + "-" + std::to_string(counter++));
        if (fs::create_directory(p)) return p;
    }
    throw std::runtime_error("cannot create a temporary directory for the variant elements");
}

struct RemoveDirectory {
    fs::path path;
    ~RemoveDirectory() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

}  // namespace

std::optional<Placement> SubstitutingRule::place(const LeafContext& context) const {
    auto p = base_->place(context);
    if (p && p->element == from_) p->element = to_;
    return p;
}

std::uint8_t region_mask(Region region) {
    switch (region) {
        case Region::Flat: return 0b11001100;
        case Region::ConcaveEdge: return 0b00111111;
        case Region::ConcaveCorner: return 0b01111111;
    }
    return 0;
}

std::string region_element(Region region) {
    switch (region) {
        case Region::Flat: return "F";
        case Region::ConcaveEdge: return "E";
        case Region::ConcaveCorner: return "VC";
    }
    return "";
}

ElementLibrary library_with(const std::vector<ElementData>& extra, const fs::path& shipped) {
    const RemoveDirectory dir{fresh_directory()};
    for (const auto& entry : fs::directory_iterator(shipped))
        if (entry.is_regular_file() && entry.path().extension() == ".element")
            fs::copy_file(entry.path(), dir.path / entry.path().filename());
    for (const auto& e : extra) {
        const fs::path file = dir.path / (e.name + ".element");
        if (fs::exists(file)) throw SchemeFormatError(file.string(), 0, "element name collides: " + e.name);
        std::ofstream out(file);
        write_element(out, e, {"crossing variant (schemes/variants.hpp), written for a check"});
    }
    return ElementLibrary::load(dir.path);
}

std::vector<std::size_t> ranking_key(const std::map<int, std::size_t>& v) {
    std::vector<std::size_t> key;
    key.push_back(v.empty() ? 0 : static_cast<std::size_t>(v.rbegin()->first));
    for (int k = 12; k >= 5; --k) {
        const auto it = v.find(k);
        key.push_back(it == v.end() ? 0 : it->second);
    }
    return key;
}

std::size_t singular_edges(const std::map<int, std::size_t>& v) {
    std::size_t n = 0;
    for (const auto& [k, c] : v)
        if (k != 4) n += c;
    return n;
}

namespace {

VariantResult describe(const Variant& v, const ElementLibrary* shipped) {
    VariantResult r;
    r.name = v.name;
    r.assignment = v.assignment;
    const ElementCheckReport check = check_element(v.complex, ElementBox{{0, 0, 0}, kLeaf}, v.labels);
    r.element_valid = check.ok();
    for (const auto& issue : check.issues) r.element_issues.push_back(issue.message);
    r.element_faces = face_size_histogram(v.complex);
    r.bend_faces = cells_face_histogram(v.complex, v.bend_cells);
    r.bend_face_size = r.bend_faces.empty() ? 0 : r.bend_faces.rbegin()->first;
    if (shipped) {
        const ComplexForm form = canonical_form(v.complex);
        for (const auto& e : shipped->elements())
            if (canonical_form(e.complex) == form) r.shipped = e.name;
    }
    return r;
}

void install(VariantResult& r, const Variant& v, const ElementLibrary& library) {
    const StrongRule strong;
    const SubstitutingRule rule(strong, region_element(v.region), v.name);
    r.torus = check_periodic_configuration(region_mask(v.region), rule, library);
}

}  // namespace

VariantResult check_variant(const Variant& v, const ElementLibrary* shipped) {
    VariantResult r = describe(v, shipped);
    try {
        const ElementLibrary library = library_with({v.element_data()});
        install(r, v, library);
    } catch (const std::exception& e) {
        r.torus = ConfigurationReport{};
        r.torus.mask = region_mask(v.region);
        r.torus.built = false;
        r.torus.error = e.what();
    }
    return r;
}

RegionReport check_region(Region region, const ElementLibrary& shipped) {
    RegionReport out;
    out.region = region;
    out.mask = region_mask(region);
    const std::vector<Variant> variants = region_variants(region);
    std::vector<ElementData> data;
    for (const auto& v : variants) data.push_back(v.element_data());
    std::optional<ElementLibrary> library;
    try {
        library = library_with(data, shipped.directory());
    } catch (const std::exception&) {
        // one of them is refused: check each on its own so the others still get results
    }
    for (const auto& v : variants) {
        if (library) {
            VariantResult r = describe(v, &shipped);
            install(r, v, *library);
            out.variants.push_back(std::move(r));
        } else {
            out.variants.push_back(check_variant(v, &shipped));
        }
        if (out.variants.back().ok()) ++out.valid;
    }
    // classes by canonical form
    std::vector<ComplexForm> forms;
    for (const auto& v : variants) forms.push_back(canonical_form(v.complex));
    std::vector<bool> done(variants.size(), false);
    for (std::size_t i = 0; i < variants.size(); ++i) {
        if (done[i]) continue;
        VariantClass c;
        for (std::size_t j = i; j < variants.size(); ++j)
            if (!done[j] && forms[j] == forms[i]) {
                done[j] = true;
                c.members.push_back(j);
                const auto& a = out.variants[i];
                const auto& b = out.variants[j];
                if (a.element_faces != b.element_faces || a.bend_faces != b.bend_faces ||
                    a.torus.dual_edge_valences != b.torus.dual_edge_valences)
                    c.histograms_agree = false;
            }
        c.ranking = ranking_key(out.variants[i].torus.dual_edge_valences);
        out.classes.push_back(std::move(c));
    }
    std::stable_sort(out.classes.begin(), out.classes.end(),
                     [](const VariantClass& a, const VariantClass& b) { return a.ranking < b.ranking; });
    for (std::size_t k = 0; k < out.classes.size(); ++k)
        out.classes[k].rank = k > 0 && out.classes[k].ranking == out.classes[k - 1].ranking
                                  ? out.classes[k - 1].rank
                                  : static_cast<int>(k) + 1;
    return out;
}

bool VariantsReport::ok() const {
    static const std::map<Region, std::size_t> kClasses{
        {Region::Flat, 1}, {Region::ConcaveEdge, 3}, {Region::ConcaveCorner, 2}};
    static const std::map<Region, std::string> kBest{
        {Region::Flat, "F"}, {Region::ConcaveEdge, "E"}, {Region::ConcaveCorner, "VC"}};
    if (regions.size() != 3) return false;
    for (const auto& r : regions) {
        if (r.valid != r.variants.size() || r.variants.size() != assignment_count(r.region)) return false;
        if (r.classes.size() != kClasses.at(r.region)) return false;
        if (r.classes.front().rank != 1 || (r.classes.size() > 1 && r.classes[1].rank == 1)) return false;
        if (r.variants[r.classes.front().members.front()].shipped != kBest.at(r.region)) return false;
        for (const auto& c : r.classes)
            if (!c.histograms_agree) return false;
    }
    return true;
}

VariantsReport check_variants(bool combined, std::size_t max_free, const Progress& progress) {
    const ElementLibrary shipped = ElementLibrary::load_default();
    VariantsReport out;
    for (Region r : {Region::Flat, Region::ConcaveEdge, Region::ConcaveCorner})
        out.regions.push_back(check_region(r, shipped));
    if (combined) out.combined = check_combined(shipped, max_free, progress);
    return out;
}

}  // namespace dualhex::variants
