#include "dualhex/schemes/placement.hpp"

#include <sstream>

namespace dualhex {

namespace {

void check_index(int i, int j, int k) {
    auto bad = [](int v) { return v < -2 || v > 1; };
    if (bad(i) || bad(j) || bad(k))
        throw std::out_of_range("LeafContext: octant index (" + std::to_string(i) + "," + std::to_string(j) + "," +
                                std::to_string(k) + ") outside {-2,-1,0,1}^3");
}

}  // namespace

bool LeafContext::fine(int i, int j, int k) const {
    check_index(i, j, k);
    return (neighbourhood >> neighbourhood_bit(i, j, k)) & 1U;
}

void LeafContext::set_fine(int i, int j, int k, bool value) {
    check_index(i, j, k);
    const std::uint64_t bit = std::uint64_t{1} << neighbourhood_bit(i, j, k);
    neighbourhood = value ? (neighbourhood | bit) : (neighbourhood & ~bit);
}

std::uint8_t LeafContext::local_configuration() const {
    std::uint8_t mask = 0;
    for (int b = 0; b < 8; ++b) {
        const int i = (b & 1) ? 0 : -1, j = (b & 2) ? 0 : -1, k = (b & 4) ? 0 : -1;
        if ((neighbourhood >> neighbourhood_bit(i, j, k)) & 1U) mask = static_cast<std::uint8_t>(mask | (1U << b));
    }
    return mask;
}

std::string LeafContext::local_pattern_name() const {
    // Order as in the derivation notes: X, Y, XY, Z, XZ, YZ, XYZ (m = negative-axis bits).
    std::string out = "{";
    bool first = true;
    for (int m = 1; m < 8; ++m) {
        const int i = (m & 1) ? -1 : 0, j = (m & 2) ? -1 : 0, k = (m & 4) ? -1 : 0;
        if (!((neighbourhood >> neighbourhood_bit(i, j, k)) & 1U)) continue;
        if (!first) out += ',';
        first = false;
        if (m & 1) out += 'X';
        if (m & 2) out += 'Y';
        if (m & 4) out += 'Z';
    }
    return out + "}";
}

CubeSymmetry LeafContext::frame() const { return CubeSymmetry({0, 1, 2}, direction); }

std::string LeafContext::describe() const {
    std::ostringstream os;
    os << "P=" << application_point << " d=(" << direction[0] << ',' << direction[1] << ',' << direction[2]
       << ") pattern " << local_pattern_name() << " neighbourhood 0x" << std::hex << neighbourhood;
    return os.str();
}

std::uint64_t to_local_neighbourhood(std::uint64_t world, const std::array<int, 3>& direction) {
    if (direction[0] > 0 && direction[1] > 0 && direction[2] > 0) return world;
    std::uint64_t local = 0;
    while (world != 0) {
        const int b = __builtin_ctzll(world);
        world &= world - 1;
        int idx[3] = {b & 3, (b >> 2) & 3, (b >> 4) & 3};
        for (int a = 0; a < 3; ++a)
            if (direction[static_cast<std::size_t>(a)] < 0) idx[a] = 3 - idx[a];  // i <-> -1 - i
        local |= std::uint64_t{1} << (idx[0] + 4 * idx[1] + 16 * idx[2]);
    }
    return local;
}

CubeSymmetry world_symmetry(const LeafContext& context, const Placement& placement) {
    return context.frame().compose(placement.symmetry);
}

TransitionRule::~TransitionRule() = default;

std::optional<Placement> FlatOnlyRule::place(const LeafContext& context) const {
    std::uint8_t around = 0;  // bit m: the octant whose negative local axes are m's bits
    for (int m = 1; m < 8; ++m)
        if (context.fine((m & 1) ? -1 : 0, (m & 2) ? -1 : 0, (m & 4) ? -1 : 0)) around = static_cast<std::uint8_t>(around | (1U << m));
    if (around == 0) return std::nullopt;
    constexpr std::uint8_t kFlat = (1U << 2) | (1U << 3) | (1U << 6) | (1U << 7);  // Y, XY, YZ, XYZ
    if (around == kFlat) return Placement{"F", CubeSymmetry{}};
    throw UnknownPatternError("flat-only rule: no element for local pattern " + context.local_pattern_name() + " (" +
                              context.describe() + ")");
}

}  // namespace dualhex
