#include "dualhex/install/element_templates.hpp"

#include <numeric>
#include <stdexcept>

#include "dualhex/schemes/element_library.hpp"
#include "dualhex/topology/primitives.hpp"

namespace dualhex::detail {

std::int64_t common_unit(const ElementLibrary& library) {
    std::int64_t u = 1;
    for (const Element& e : library.elements()) u = std::lcm(u, e.leaf());
    return u % 2 == 0 ? u : 2 * u;
}

TemplateCache::TemplateCache(const ElementLibrary& library) : library_(&library), unit_(common_unit(library)) {}

const ElementTemplate& TemplateCache::hex(std::int64_t size) {
    auto it = hexes_.find(size);
    if (it != hexes_.end()) return it->second;
    ElementTemplate t;
    for (int c = 0; c < 8; ++c) t.points.push_back({(c & 1) * size, ((c >> 1) & 1) * size, ((c >> 2) & 1) * size});
    auto index = [&](const LatticePoint& p) {
        for (std::uint32_t n = 0; n < 8; ++n)
            if (t.points[n] == p) return n;
        throw std::logic_error("hex template: corner not found");
    };
    for (const auto& loop : cube_loops({0, 0, 0}, size)) {
        for (const auto& p : loop) t.face_points.push_back(index(p));
        t.face_offsets.push_back(static_cast<std::uint32_t>(t.face_points.size()));
    }
    t.cell_offsets.push_back(6);
    return hexes_.emplace(size, std::move(t)).first->second;
}

int TemplateCache::element_index(const std::string& name) {
    auto it = index_.find(name);
    if (it != index_.end()) return it->second;
    (void)library_->at(name);  // throws std::out_of_range naming the known elements
    const int n = static_cast<int>(names_.size());
    names_.push_back(name);
    std::array<int, 48> empty{};
    empty.fill(-1);
    slot_.push_back(empty);
    index_.emplace(name, n);
    return n;
}

const ElementTemplate& TemplateCache::placed(int element, const CubeSymmetry& world) {
    int& slot = slot_[static_cast<std::size_t>(element)][static_cast<std::size_t>(world.index())];
    if (slot >= 0) return templates_[static_cast<std::size_t>(slot)];
    const std::string& name = names_[static_cast<std::size_t>(element)];
    const Element& e = library_->at(name);
    const std::int64_t scale = unit_ / e.leaf();
    const CellComplex cx = library_->instance(name, world);
    ElementTemplate t;
    t.element = name;
    for (const LatticePoint& p : cx.positions()) t.points.push_back(p * scale);
    for (std::size_t c = 0; c < cx.n_cells(); ++c) {
        for (HalfFaceHandle h : cx.cell_halffaces(CellHandle(c))) {
            for (VertexHandle v : cx.halfface_vertices(h)) t.face_points.push_back(static_cast<std::uint32_t>(v.index()));
            t.face_offsets.push_back(static_cast<std::uint32_t>(t.face_points.size()));
        }
        t.cell_offsets.push_back(static_cast<std::uint32_t>(t.face_offsets.size() - 1));
    }
    slot = static_cast<int>(templates_.size());
    templates_.push_back(std::move(t));
    return templates_.back();
}

void check_placement_symmetry(const Placement& placement) {
    const CubeSymmetry& s = placement.symmetry;
    if (s.sign(0) < 0 || s.sign(1) < 0 || s.sign(2) < 0)
        throw std::invalid_argument("placement of element '" + placement.element + "' by " + s.to_string() +
                                    " moves it out of its leaf: in the leaf's local frame only the 6 axis "
                                    "permutations keep [0,1]^3 in place");
}

}  // namespace dualhex::detail
