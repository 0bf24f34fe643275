#pragma once
// Internal: the face loops of one clipped dual cell, and the check that they form an
// oriented combinatorial cube (clipped_dual.hpp says why every dual cell must be one).
#include <array>
#include <cstddef>
#include <cstdint>

namespace dualhex::detail {

// Per-vertex scratch: up to 6 face loops (more = not a cube; we stop collecting).
struct DualCellFaces {
    static constexpr std::size_t kMaxFaces = 8, kMaxLoop = 12;
    std::array<std::array<std::uint32_t, kMaxLoop>, kMaxFaces> loop{};
    std::array<std::uint8_t, kMaxFaces> size{};
    std::size_t n = 0;
    bool overflow = false;
    const char* why = nullptr;  // first construction failure

    void clear() {
        n = 0;
        overflow = false;
        why = nullptr;
    }
    // Starts a new face; false (and overflow) if there are too many.
    bool open() {
        if (n == kMaxFaces) {
            overflow = true;
            return false;
        }
        size[n++] = 0;
        return true;
    }
    void push(std::uint32_t id) {
        std::uint8_t& s = size[n - 1];
        if (s == kMaxLoop) {
            overflow = true;
            return;
        }
        loop[n - 1][s++] = id;
    }
    void fail(const char* reason) {
        if (!why) why = reason;
    }
};

// Checks `faces` is an oriented combinatorial cube; fills hex (VTK order) or returns why not.
// The 8 dual vertices get slots 0..7 (first appearance); directed dual edges are bits of
// an 8x8 matrix (row = tail slot), so the checks are bit operations. The reasons and
// their precedence are those of a plain list check: per face (quad, repeated vertex,
// more than 8 vertices), then fewer than 8, an edge walked twice, an edge in one face,
// degree above / below 3, connectivity, the cube's vertical edges.
[[nodiscard]] const char* oriented_cube(const DualCellFaces& faces, std::array<std::uint32_t, 8>& hex);

}  // namespace dualhex::detail
