// The combined ranking (variants_report.hpp, check_combined): every crossing of the 20
// transitions left free, each assignment installed on the tori and ranked against the
// shipped rule.
#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <iomanip>
#include <ostream>
#include <random>
#include <set>
#include <sstream>
#include <unordered_map>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/variants_report.hpp"
#include "dualhex/schemes/element_check.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/histograms.hpp"

namespace dualhex::variants {
namespace {

constexpr std::array<std::array<int, 3>, 6> kPermutations{{
    {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

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

bool CombinedReport::strong_optimal() const {
    return std::all_of(classes.begin(), classes.end(), [](const CombinedClass& c) { return c.strong_optimal(); });
}

namespace {

// One transition class before its enumeration: the free crossings, StrongRule's choice at
// each, and the groups of crossings enumerated jointly (empty: too many to enumerate).
struct PreparedClass {
    CombinedClass c;
    std::vector<std::size_t> strong_key;
    std::map<int, std::array<int, 2>> options;  // crossing key -> the two chain axes
    std::unordered_map<int, int> strong_lower;
    std::vector<std::vector<int>> groups;
    [[nodiscard]] std::size_t assignments() const {
        std::size_t n = 0;
        if (c.enumerated)
            for (const auto& g : groups) n += std::size_t{1} << g.size();
        return n;
    }
};

PreparedClass prepare_class(std::uint8_t rep, const TransitionRule& strong, const ElementLibrary& library,
                            std::size_t max_free) {
    PreparedClass p;
    CombinedClass& c = p.c;
    c.representative = rep;
    for (int b = 0; b < 8; ++b) c.fine += (rep >> b) & 1;
    const ConfigurationReport strong_report = check_periodic_configuration(rep, strong, library);
    c.strong_valences = strong_report.dual_edge_valences;
    p.strong_key = ranking_key(c.strong_valences);
    // free crossings: those on an interface face of a leaf with two or three interfaces
    const ConfigurationComplex built = build_periodic_configuration(rep, strong, library);
    auto& options = p.options;
    for (const auto& leaf : built.coarse_leaves) {
        const Signature s = required_signature(leaf.context);
        if (std::popcount(s.interfaces) < 2) continue;
        for (int n = 0; n < 3; ++n)
            if (s.interfaces & (1u << n)) options[crossing_key(leaf.context, n)] = {(n + 1) % 3, (n + 2) % 3};
    }
    c.free_crossings = options.size();
    // StrongRule's lower chain at every free crossing, and the components of the free
    // crossings linked by a leaf that sees two or three of them.
    std::unordered_map<int, int> parent;
    std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
    for (const auto& [key, axes] : options) parent[key] = key;
    for (const auto& leaf : built.coarse_leaves) {
        const Signature s = required_signature(leaf.context);
        int first = -1;
        for (int n = 0; n < 3; ++n) {
            if (!(s.interfaces & (1u << n)) || !options.count(crossing_key(leaf.context, n))) continue;
            const int key = crossing_key(leaf.context, n);
            p.strong_lower[key] = s.lower[n];
            if (std::popcount(s.interfaces) < 2) continue;
            if (first < 0) first = key;
            else parent[find(key)] = find(first);
        }
    }
    std::map<int, std::vector<int>> components;
    for (const auto& [key, axes] : options) components[find(key)].push_back(key);
    if (options.size() <= max_free) {
        p.groups.emplace_back();
        for (const auto& [key, axes] : options) p.groups.back().push_back(key);
    } else {
        c.componentwise = true;
        for (auto& [root, keys] : components) p.groups.push_back(keys);
    }
    for (const auto& [root, keys] : components) c.components.push_back(keys.size());
    std::sort(c.components.rbegin(), c.components.rend());
    c.enumerated = std::none_of(p.groups.begin(), p.groups.end(), [&](const auto& g) { return g.size() > max_free; });
    return p;
}

// Every assignment of each group installed and ranked against StrongRule's.
void enumerate_class(PreparedClass& p, const ElementLibrary& library, ProgressCounter& counter) {
    CombinedClass& c = p.c;
    std::vector<std::size_t> best_key;
    std::unordered_map<int, int> lower;
    const CrossingRule rule(lower);
    for (const auto& group : p.groups)
        for (std::size_t bits = 0; bits < (std::size_t{1} << group.size()); ++bits) {
            lower = p.strong_lower;  // crossings outside the group keep StrongRule's choice
            for (std::size_t k = 0; k < group.size(); ++k) lower[group[k]] = p.options.at(group[k])[(bits >> k) & 1];
            ++c.assignments;
            const ConfigurationReport r = check_periodic_configuration(c.representative, rule, library);
            counter.add();
            if (!r.ok()) continue;
            ++c.valid;
            const auto key = ranking_key(r.dual_edge_valences);
            if (key < p.strong_key) ++c.assignments_better;
            if (key == p.strong_key) ++c.assignments_equal;
            if (best_key.empty() || key < best_key) {
                best_key = key;
                c.best_valences = r.dual_edge_valences;
            }
        }
}

}  // namespace

CombinedReport check_combined(const ElementLibrary& shipped, std::size_t max_free, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    CombinedReport out;
    out.limit = max_free;
    const ElementLibrary library = library_with(
        {build_variant(Region::ConcaveEdge, "UU").element_data(), build_variant(Region::ConcaveCorner, "XXY").element_data()},
        shipped.directory());
    std::set<std::uint8_t> representatives;
    for (int m = 1; m < 255; ++m) representatives.insert(class_representative(static_cast<std::uint8_t>(m)));
    const StrongRule strong;
    // All classes prepared first, so the progress counts assignments of the whole run.
    std::vector<PreparedClass> prepared;
    std::size_t total = 0;
    for (std::uint8_t rep : representatives) {
        prepared.push_back(prepare_class(rep, strong, library, max_free));
        total += prepared.back().assignments();
    }
    ProgressCounter counter(progress, "assignments", total);
    for (PreparedClass& p : prepared) {
        if (p.c.enumerated) enumerate_class(p, library, counter);
        out.classes.push_back(std::move(p.c));
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

}  // namespace dualhex::variants
