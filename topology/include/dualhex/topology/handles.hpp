#pragma once
// Strong handle types (after OpenVolumeMesh): an index that knows what it indexes, so a
// face id can never be passed where a cell id is expected.
//
// Half-faces follow the `2 * face + side` convention: side 0 walks the face's stored
// vertex loop as written, side 1 walks it reversed, and `opposite()` is `h ^ 1`.
#include <compare>
#include <cstdint>
#include <functional>

namespace dualhex {

template <class Tag>
struct Handle {
    std::int32_t idx = -1;

    constexpr Handle() = default;
    constexpr explicit Handle(std::int32_t i) : idx(i) {}
    constexpr explicit Handle(std::size_t i) : idx(static_cast<std::int32_t>(i)) {}

    [[nodiscard]] constexpr bool valid() const { return idx >= 0; }
    [[nodiscard]] constexpr std::size_t index() const { return static_cast<std::size_t>(idx); }
    constexpr auto operator<=>(const Handle&) const = default;
};

using VertexHandle = Handle<struct VertexTag>;
using EdgeHandle = Handle<struct EdgeTag>;
using FaceHandle = Handle<struct FaceTag>;
using CellHandle = Handle<struct CellTag>;

/// An oriented face: `2 * face + side`. Side 0 is the stored loop, side 1 its reverse.
struct HalfFaceHandle : Handle<struct HalfFaceTag> {
    using Handle::Handle;
    constexpr HalfFaceHandle(FaceHandle f, int side) : Handle(2 * f.idx + (side & 1)) {}
    [[nodiscard]] constexpr FaceHandle face() const { return FaceHandle(idx >> 1); }
    [[nodiscard]] constexpr int side() const { return idx & 1; }
    [[nodiscard]] constexpr HalfFaceHandle opposite() const { return HalfFaceHandle(idx ^ 1); }
};

}  // namespace dualhex

template <class Tag>
struct std::hash<dualhex::Handle<Tag>> {
    std::size_t operator()(const dualhex::Handle<Tag>& h) const noexcept { return std::hash<std::int32_t>{}(h.idx); }
};
