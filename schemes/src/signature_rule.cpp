#include "dualhex/schemes/signature_rule.hpp"

#include <algorithm>
#include <sstream>

namespace dualhex {
namespace {

constexpr std::array<std::array<int, 3>, 6> kPermutations{{
    {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

bool fine_at(const LeafContext& c, std::array<int, 3> o) { return c.fine(o[0], o[1], o[2]); }

std::array<int, 3> unit(int axis, int sign) {
    std::array<int, 3> u{0, 0, 0};
    u[static_cast<std::size_t>(axis)] = sign;
    return u;
}

Signature make(unsigned interfaces, unsigned tets, std::initializer_list<std::pair<int, int>> lower) {
    Signature s;
    s.interfaces = interfaces;
    s.tets = tets;
    for (const auto& [n, a] : lower) s.lower[n] = a;
    return s;
}

}  // namespace

Signature Signature::permuted(const std::array<int, 3>& s) const {
    Signature out;
    for (int a = 0; a < 3; ++a) {
        if (interfaces & (1u << a)) out.interfaces |= 1u << s[static_cast<std::size_t>(a)];
        if (tets & (1u << a)) out.tets |= 1u << s[static_cast<std::size_t>(a)];
        if (lower[a] >= 0) out.lower[s[static_cast<std::size_t>(a)]] = s[static_cast<std::size_t>(lower[a])];
    }
    return out;
}

std::string Signature::to_string() const {
    static constexpr char kAxis[] = {'x', 'y', 'z'};
    std::ostringstream os;
    os << "interfaces {";
    for (int a = 0; a < 3; ++a)
        if (interfaces & (1u << a)) os << kAxis[a];
    os << "} tets {";
    for (int a = 0; a < 3; ++a)
        if (tets & (1u << a)) os << kAxis[a];
    os << "} lower {";
    for (int n = 0; n < 3; ++n)
        if (lower[n] >= 0) os << ' ' << kAxis[n] << ':' << kAxis[lower[n]];
    os << " }";
    return os.str();
}

Signature required_signature(const LeafContext& c) {
    Signature s;
    bool face[3], side[3];  // inner face a is an interface; Q has an interface normal to a
    for (int a = 0; a < 3; ++a) {
        face[a] = fine_at(c, unit(a, -1));
        side[a] = face[a] || fine_at(c, unit(a, +1));
        if (face[a]) s.interfaces |= 1u << a;
    }
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, d = (a + 2) % 3;
        auto diagonal = unit(b, -1);
        diagonal[static_cast<std::size_t>(d)] = -1;
        if (!face[b] && !face[d] && fine_at(c, diagonal)) s.tets |= 1u << a;
    }
    for (int n = 0; n < 3; ++n) {
        if (!face[n]) continue;
        const int a = (n + 1) % 3, b = (n + 2) % 3;  // chain over the a-mid-plane runs along b
        const bool bent_along_b = side[b], bent_along_a = side[a];
        s.lower[n] = bent_along_b != bent_along_a ? (bent_along_b ? b : a) : (n + 1) % 3;
    }
    return s;
}

const std::vector<CanonicalElement>& strong_elements() {
    // Canonical frames (schemes/elements/*.element): F's interface is y=0 and its lower chain
    // runs along x; E's and VS's interfaces are y=0 and z=0; C1's tetrahedron ends the x-edge.
    static const std::vector<CanonicalElement> kElements = {
        {"F", make(0b010, 0b000, {{1, 0}})},
        {"F+C", make(0b010, 0b010, {{1, 0}})},
        {"C1", make(0b000, 0b001, {})},
        {"C2", make(0b000, 0b011, {})},
        {"C3", make(0b000, 0b111, {})},
        {"E", make(0b110, 0b000, {{1, 2}, {2, 1}})},
        {"VS", make(0b110, 0b000, {{1, 2}, {2, 0}})},
        {"VC", make(0b111, 0b000, {{1, 2}, {2, 0}, {0, 1}})},
    };
    return kElements;
}

const std::array<std::array<int, 3>, 6>& axis_permutations() { return kPermutations; }

Placement permutation_placement(const std::string& element, const std::array<int, 3>& s) {
    std::array<int, 3> inverse{};  // image[s[i]] = p[i], i.e. perm = s^-1
    for (int i = 0; i < 3; ++i) inverse[static_cast<std::size_t>(s[static_cast<std::size_t>(i)])] = i;
    return Placement{element, CubeSymmetry(inverse, {1, 1, 1})};
}

std::uint64_t strong_reach() {
    std::uint64_t reach = std::uint64_t{1} << LeafContext::neighbourhood_bit(0, 0, 0);
    for (int a = 0; a < 3; ++a) {
        const auto bit = [](const std::array<int, 3>& o) {
            return std::uint64_t{1} << LeafContext::neighbourhood_bit(o[0], o[1], o[2]);
        };
        auto diagonal = unit((a + 1) % 3, -1);
        diagonal[static_cast<std::size_t>((a + 2) % 3)] = -1;
        reach |= bit(unit(a, -1)) | bit(unit(a, +1)) | bit(diagonal);
    }
    return reach;
}

std::optional<Placement> StrongRule::place(const LeafContext& context) const {
    LeafContext visible = context;  // what the rule may see: its reach, nothing else
    visible.neighbourhood &= strong_reach();
    visible.edge_two_finer = 0;
    const Signature need = required_signature(visible);
    if (need.empty()) return std::nullopt;
    for (const auto& e : strong_elements())
        for (const auto& s : kPermutations)
            if (e.signature.permuted(s) == need) return permutation_placement(e.name, s);
    throw UnknownPatternError("no strongly balanced element has signature " + need.to_string() + " (" +
                              context.describe() + ")");
}

}  // namespace dualhex
