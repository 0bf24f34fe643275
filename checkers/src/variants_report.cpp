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

constexpr std::array<std::array<int, 3>, 6> kPermutations{{
    {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

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

std::string histogram_columns(const std::map<int, std::size_t>& h, int from = 3, int to = 7) {
    std::string out;
    for (int k = from; k <= to; ++k) {
        if (k > from) out += '/';
        const auto it = h.find(k);
        out += std::to_string(it == h.end() ? 0 : it->second);
    }
    return out;
}

Signature make_signature(unsigned interfaces, std::initializer_list<std::pair<int, int>> lower) {
    Signature s;
    s.interfaces = interfaces;
    for (const auto& [n, a] : lower) s.lower[n] = a;
    return s;
}

// The shipped elements plus the two the shipped set lacks (a concave edge whose turning chain
// is above both crossings; a non-cyclic concave corner), with canonical signatures.
const std::vector<CanonicalElement>& extended_elements() {
    static const std::vector<CanonicalElement> kElements = [] {
        std::vector<CanonicalElement> e = strong_elements();
        e.push_back({"edge-UU", make_signature(0b110, {{1, 0}, {2, 0}})});
        e.push_back({"corner-XXY", make_signature(0b111, {{1, 2}, {2, 1}, {0, 2}})});
        return e;
    }();
    return kElements;
}

// The crossing on interface face n of a leaf (the leaf's far corner on that face), as a
// torus point (coarse units mod 4) packed into an int.
int crossing_key(const LeafContext& c, int n) {
    int key = 0;
    for (int a = 0; a < 3; ++a) {
        std::int64_t x = c.application_point[a];
        if (a != n) x += c.direction[static_cast<std::size_t>(a)];
        key = key * 4 + static_cast<int>(((x % 4) + 4) % 4);
    }
    return key;
}

// StrongRule's signature with the lower chain at some crossings taken from a table
// (crossing key -> axis of the lower chain).
class CrossingRule : public TransitionRule {
public:
    explicit CrossingRule(const std::unordered_map<int, int>& lower) : lower_(&lower) {}
    [[nodiscard]] std::optional<Placement> place(const LeafContext& context) const override {
        Signature need = required_signature(context);
        if (need.empty()) return std::nullopt;
        for (int n = 0; n < 3; ++n) {
            if (!(need.interfaces & (1u << n))) continue;
            const auto it = lower_->find(crossing_key(context, n));
            if (it != lower_->end()) need.lower[n] = it->second;
        }
        for (const auto& e : extended_elements())
            for (const auto& s : kPermutations)
                if (e.signature.permuted(s) == need) {
                    std::array<int, 3> inverse{};
                    for (int i = 0; i < 3; ++i) inverse[static_cast<std::size_t>(s[static_cast<std::size_t>(i)])] = i;
                    return Placement{e.name, CubeSymmetry(inverse, {1, 1, 1})};
                }
        throw UnknownPatternError("no element has signature " + need.to_string());
    }
    [[nodiscard]] std::string name() const override { return "crossings"; }

private:
    const std::unordered_map<int, int>* lower_;
};

// Torus-convention masks under the 48 symmetries: the smallest image.
std::uint8_t class_representative(std::uint8_t mask) {
    std::uint8_t best = mask;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        const CubeSymmetry s = CubeSymmetry::from_index(i);
        std::uint8_t image = 0;
        for (int b = 0; b < 8; ++b) {
            if (!((mask >> b) & 1)) continue;
            const int c[3] = {b & 1, (b >> 1) & 1, (b >> 2) & 1};
            int t = 0;
            for (int a = 0; a < 3; ++a) {
                const int v = c[s.perm(a)];
                t |= (s.sign(a) > 0 ? v : 1 - v) << a;
            }
            image = static_cast<std::uint8_t>(image | (1u << t));
        }
        best = std::min(best, image);
    }
    return best;
}

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

bool CombinedReport::strong_optimal() const {
    return std::all_of(classes.begin(), classes.end(), [](const CombinedClass& c) { return c.strong_optimal(); });
}

CombinedReport check_combined(const ElementLibrary& shipped, std::size_t max_free) {
    const auto t0 = std::chrono::steady_clock::now();
    CombinedReport out;
    out.limit = max_free;
    const ElementLibrary library = library_with(
        {build_variant(Region::ConcaveEdge, "UU").element_data(), build_variant(Region::ConcaveCorner, "XXY").element_data()},
        shipped.directory());
    std::set<std::uint8_t> representatives;
    for (int m = 1; m < 255; ++m) representatives.insert(class_representative(static_cast<std::uint8_t>(m)));
    const StrongRule strong;
    for (std::uint8_t rep : representatives) {
        CombinedClass c;
        c.representative = rep;
        for (int b = 0; b < 8; ++b) c.fine += (rep >> b) & 1;
        const ConfigurationReport strong_report = check_periodic_configuration(rep, strong, library);
        c.strong_valences = strong_report.dual_edge_valences;
        const auto strong_key = ranking_key(c.strong_valences);
        // free crossings: those on an interface face of a leaf with two or three interfaces
        const ConfigurationComplex built = build_periodic_configuration(rep, strong, library);
        std::map<int, std::array<int, 2>> options;  // key -> the two chain axes
        for (const auto& leaf : built.coarse_leaves) {
            const Signature s = required_signature(leaf.context);
            if (std::popcount(s.interfaces) < 2) continue;
            for (int n = 0; n < 3; ++n)
                if (s.interfaces & (1u << n)) options[crossing_key(leaf.context, n)] = {(n + 1) % 3, (n + 2) % 3};
        }
        c.free_crossings = options.size();
        // StrongRule's lower chain at every free crossing, and the components of the free
        // crossings linked by a leaf that sees two or three of them.
        std::unordered_map<int, int> strong_lower, parent;
        std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
        for (const auto& [key, axes] : options) parent[key] = key;
        for (const auto& leaf : built.coarse_leaves) {
            const Signature s = required_signature(leaf.context);
            int first = -1;
            for (int n = 0; n < 3; ++n) {
                if (!(s.interfaces & (1u << n)) || !options.count(crossing_key(leaf.context, n))) continue;
                const int key = crossing_key(leaf.context, n);
                strong_lower[key] = s.lower[n];
                if (std::popcount(s.interfaces) < 2) continue;
                if (first < 0) first = key;
                else parent[find(key)] = find(first);
            }
        }
        std::map<int, std::vector<int>> components;
        for (const auto& [key, axes] : options) components[find(key)].push_back(key);
        std::vector<std::vector<int>> groups;
        if (options.size() <= max_free) {
            groups.emplace_back();
            for (const auto& [key, axes] : options) groups.back().push_back(key);
        } else {
            c.componentwise = true;
            for (auto& [root, keys] : components) groups.push_back(keys);
        }
        for (const auto& [root, keys] : components) c.components.push_back(keys.size());
        std::sort(c.components.rbegin(), c.components.rend());
        if (std::any_of(groups.begin(), groups.end(), [&](const auto& g) { return g.size() > max_free; })) {
            out.classes.push_back(std::move(c));
            continue;
        }
        c.enumerated = true;
        std::vector<std::size_t> best_key;
        std::unordered_map<int, int> lower;
        const CrossingRule rule(lower);
        for (const auto& group : groups)
            for (std::size_t bits = 0; bits < (std::size_t{1} << group.size()); ++bits) {
                lower = strong_lower;  // crossings outside the group keep StrongRule's choice
                for (std::size_t k = 0; k < group.size(); ++k)
                    lower[group[k]] = options.at(group[k])[(bits >> k) & 1];
                ++c.assignments;
                const ConfigurationReport r = check_periodic_configuration(rep, rule, library);
                if (!r.ok()) continue;
                ++c.valid;
                const auto key = ranking_key(r.dual_edge_valences);
                if (key < strong_key) ++c.assignments_better;
                if (key == strong_key) ++c.assignments_equal;
                if (best_key.empty() || key < best_key) {
                    best_key = key;
                    c.best_valences = r.dual_edge_valences;
                }
            }
        out.classes.push_back(std::move(c));
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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

VariantsReport check_variants(bool combined, std::size_t max_free) {
    const ElementLibrary shipped = ElementLibrary::load_default();
    VariantsReport out;
    for (Region r : {Region::Flat, Region::ConcaveEdge, Region::ConcaveCorner})
        out.regions.push_back(check_region(r, shipped));
    if (combined) out.combined = check_combined(shipped, max_free);
    return out;
}

void print(std::ostream& os, const VariantsReport& report) {
    for (const auto& r : report.regions) {
        os << to_string(r.region) << ": torus " << format_mask(r.mask) << " (every coarse leaf a "
           << region_element(r.region) << "), " << r.variants.size() << " assignments, " << r.valid << " valid, "
           << r.classes.size() << " classes\n";
        os << "  " << std::left << std::setw(12) << "assignment" << std::setw(7) << "valid" << std::setw(16)
           << "faces F3..F7" << std::setw(28) << "bend faces" << std::setw(42) << "torus dual edge valences"
           << std::setw(10) << "singular"
           << "shipped\n";
        for (const auto& v : r.variants) {
            os << "  " << std::setw(12) << v.name << std::setw(7) << (v.ok() ? "yes" : "NO") << std::setw(16)
               << histogram_columns(v.element_faces) << std::setw(28)
               << (v.bend_faces.empty() ? std::string("-") : format_histogram(v.bend_faces)) << std::setw(42)
               << (v.torus.built ? format_histogram(v.torus.dual_edge_valences) : "ERROR " + v.torus.error)
               << std::setw(10) << singular_edges(v.torus.dual_edge_valences) << (v.shipped.empty() ? "-" : v.shipped)
               << '\n';
            if (!v.ok() && v.torus.built) os << "    " << v.torus.summary() << '\n';
        }
        os << "  classes by rank (max valence, then counts of valences > 4 from high to low; lower is better):\n";
        for (const auto& c : r.classes) {
            const auto& v = r.variants[c.members.front()];
            std::string members;
            for (std::size_t m : c.members) members += (members.empty() ? "" : ",") + r.variants[m].assignment;
            os << "    rank " << c.rank << "  {" << members << "}  bend face size " << v.bend_face_size
               << "  max valence " << c.ranking.front() << "  singular " << singular_edges(v.torus.dual_edge_valences)
               << "  torus " << format_histogram(v.torus.dual_edge_valences)
               << (v.shipped.empty() ? "" : "  = " + v.shipped) << (c.histograms_agree ? "" : "  MEMBERS DIFFER")
               << '\n';
        }
        os << '\n';
    }
    if (report.combined) {
        const auto& cr = *report.combined;
        os << "combined: every crossing touched by a bend free, per transition class (torus; limit 2^" << cr.limit
           << " assignments)\n";
        os << "  " << std::left << std::setw(12) << "class" << std::setw(6) << "fine" << std::setw(6) << "free"
           << std::setw(14) << "valid/total" << std::setw(36) << "strong rule" << std::setw(36) << "best"
           << "better/equal\n";
        for (const auto& c : cr.classes) {
            os << "  " << std::setw(12) << format_mask(c.representative) << std::setw(6) << c.fine << std::setw(6)
               << c.free_crossings << std::setw(14)
               << (c.enumerated ? std::to_string(c.valid) + "/" + std::to_string(c.assignments) +
                                      (c.componentwise ? " *" : "")
                                : "skipped")
               << std::setw(36) << format_histogram(c.strong_valences) << std::setw(36)
               << (c.enumerated ? format_histogram(c.best_valences) : "-")
               << (c.enumerated ? std::to_string(c.assignments_better) + "/" + std::to_string(c.assignments_equal)
                                : "-")
               << '\n';
        }
        os << "  * too many free crossings to enumerate jointly: each component (crossings linked by a leaf\n"
              "    with two or three interfaces) enumerated with the others at StrongRule's choice; the torus\n"
              "    histogram is a sum of per-leaf terms (a leaf's inner faces plus half its boundary faces), so\n"
              "    the best joint assignment is the best per component (lexicographic order is additive)\n";
        os << "  strong rule optimal in every enumerated class: " << (cr.strong_optimal() ? "yes" : "NO") << " ("
           << std::fixed << std::setprecision(1) << cr.seconds << " s)\n";
        os.unsetf(std::ios::fixed);
    }
}

}  // namespace dualhex::variants
