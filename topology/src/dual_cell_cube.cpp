// The oriented-cube check of a clipped dual cell (dual_cell_cube.hpp).
#include "dual_cell_cube.hpp"

#include <bit>

namespace dualhex::detail {
namespace {

// Set bits of an 8-bit row (std::popcount is a libgcc call without -mpopcnt).
constexpr int bits8(unsigned x) {
    x = x - ((x >> 1) & 0x55U);
    x = (x & 0x33U) + ((x >> 2) & 0x33U);
    return static_cast<int>((x + (x >> 4)) & 0x0FU);
}

// The 8x8 bit matrix with row a in byte a (bit b = column b), transposed (three rounds of
// block swaps: 2x2, 4x4, 8x8 blocks; Warren, Hacker's Delight, section 7-3).
constexpr std::uint64_t transpose8(std::uint64_t x) {
    std::uint64_t t = (x ^ (x >> 7)) & 0x00AA00AA00AA00AAULL;
    x = x ^ t ^ (t << 7);
    t = (x ^ (x >> 14)) & 0x0000CCCC0000CCCCULL;
    x = x ^ t ^ (t << 14);
    t = (x ^ (x >> 28)) & 0x00000000F0F0F0F0ULL;
    return x ^ t ^ (t << 28);
}
static_assert(transpose8(0x0000000000000002ULL) == 0x0000000000000100ULL);  // edge 0 -> 1 becomes 1 -> 0
static_assert(transpose8(0x8000000000000000ULL) == 0x8000000000000000ULL);  // the diagonal stays

}  // namespace

// Checks `faces` is an oriented combinatorial cube; fills hex (VTK order) or returns why not.
// The 8 dual vertices get slots 0..7 (first appearance); directed dual edges are bits of
// an 8x8 matrix (row = tail slot), so the checks are bit operations. The reasons and
// their precedence are those of a plain list check: per face (quad, repeated vertex,
// more than 8 vertices), then fewer than 8, an edge walked twice, an edge in one face,
// degree above / below 3, connectivity, the cube's vertical edges.
const char* oriented_cube(const DualCellFaces& faces, std::array<std::uint32_t, 8>& hex) {
    if (faces.n != 6) return faces.n < 6 ? "fewer than 6 dual faces" : "more than 6 dual faces";
    std::array<std::uint32_t, 8> verts{};
    std::size_t nverts = 0;
    std::array<std::array<std::uint8_t, 4>, 6> slots{};
    for (std::size_t i = 0; i < 6; ++i) {
        if (faces.size[i] != 4) return "a dual face that is not a quadrilateral";
        const auto& q = faces.loop[i];
        for (std::size_t j = 0; j < 4; ++j) {
            for (std::size_t l = j + 1; l < 4; ++l)
                if (q[j] == q[l]) return "a dual face repeats a vertex";
            std::size_t s = 0;
            while (s < nverts && verts[s] != q[j]) ++s;
            if (s == nverts) {
                if (nverts == 8) return "more than 8 dual vertices";
                verts[nverts++] = q[j];
            }
            slots[i][j] = static_cast<std::uint8_t>(s);
        }
    }
    if (nverts != 8) return "fewer than 8 dual vertices";
    std::array<std::uint8_t, 8> out{};  // out[a] bit b: directed edge a -> b
    bool twice = false;
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 4; ++j) {
            const std::uint8_t a = slots[i][j], b = slots[i][(j + 1) % 4];
            const auto bit = static_cast<std::uint8_t>(1U << b);
            if (out[a] & bit) twice = true;
            out[a] |= bit;
        }
    if (twice) return "a dual edge walked twice in the same direction (faces not consistently oriented)";
    // Every directed edge a -> b has its reverse b -> a: the matrix is symmetric.
    std::uint64_t matrix = 0;
    for (std::size_t a = 0; a < 8; ++a) matrix |= std::uint64_t{out[a]} << (8 * a);
    if (matrix & ~transpose8(matrix)) return "a dual edge in only one dual face";
    // 24 directed = 12 edges, each in two faces with opposite orientations; degree 3 each.
    bool below = false;
    for (std::uint8_t row : out) {
        const int d = bits8(row);
        if (d > 3) return "a dual vertex of degree above 3";
        below = below || d < 3;
    }
    if (below) return "a dual vertex of degree below 3";
    // Connected (V - E + F = 2 then makes it a sphere, the cube).
    unsigned seen = 1, frontier = 1;
    while (frontier) {
        unsigned next = 0;
        for (std::size_t s = 0; s < 8; ++s)
            if (frontier & (1U << s)) next |= out[s];
        frontier = next & ~seen;
        seen |= next;
    }
    if (seen != 0xFF) return "the dual cell is disconnected";
    const auto& q = faces.loop[0];
    const auto& qs = slots[0];
    hex = {q[0], q[3], q[2], q[1], 0, 0, 0, 0};
    const unsigned ring = (1U << qs[0]) | (1U << qs[1]) | (1U << qs[2]) | (1U << qs[3]);
    constexpr std::size_t kRing[4] = {0, 3, 2, 1};
    for (std::size_t i = 0; i < 4; ++i) {
        const unsigned rest = out[qs[kRing[i]]] & ~ring;
        if (bits8(rest) != 1) return "the dual cell is not a cube";
        hex[i + 4] = verts[static_cast<std::size_t>(std::countr_zero(rest))];
    }
    return nullptr;
}

}  // namespace dualhex::detail
