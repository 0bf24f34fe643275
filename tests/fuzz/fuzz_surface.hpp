#pragma once
// The body of the surface-reader harnesses (fuzz_obj/off/stl/ply.cpp): one reader on
// arbitrary bytes, then, for what it accepts, the rest of read_surface's checks
// (clean_surface without requiring closedness, the exact self-intersection search), so the
// fuzzer also reaches them with odd geometry. Only SurfaceError may come out; anything else
// (a crash, a sanitizer report, another exception, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "dualhex/geometry/self_intersection.hpp"
#include "dualhex/geometry/surface.hpp"
#include "surface_parse.hpp"

namespace dualhex::fuzz {

template <class Reader>
int read_surface_bytes(const std::uint8_t* data, std::size_t size, Reader read, const std::string& name) {
    using namespace dualhex::geometry;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        detail::PolygonSoup soup = read(bytes, name);
        if (soup.triangles.size() > 256) return 0;  // keep each run short (mutated models: giant triangles)
        TriangleSurface s;
        s.source = name;
        s.vertices = std::move(soup.points);
        s.triangles = std::move(soup.triangles);
        s = clean_surface(std::move(s), {.require_closed = false});
        (void)find_self_intersections(s);
    } catch (const SurfaceError&) {
    }
    return 0;
}

}  // namespace dualhex::fuzz
