// Scene JSON of a complex: vertices, faces, cells with roles, and the dual hexes.
#include "dualhex/atlas/scene.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/dual.hpp"

namespace dualhex::atlas {
namespace {

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

/// The distinct vertices of a cell.
std::vector<VertexHandle> cell_vertices(const CellComplex& complex, CellHandle c) {
    std::set<VertexHandle> seen;
    for (HalfFaceHandle h : complex.cell_halffaces(c))
        for (VertexHandle v : complex.face_vertices(h.face())) seen.insert(v);
    return {seen.begin(), seen.end()};
}

/// Exact centroid of a cell's vertices: (sum, count).
RationalPoint cell_centroid(const CellComplex& complex, CellHandle c) {
    RationalPoint p{{0, 0, 0}, 0};
    for (VertexHandle v : cell_vertices(complex, c)) {
        p.sum = p.sum + complex.position(v);
        ++p.denominator;
    }
    return p;
}

nlohmann::json point_json(const RationalPoint& p) {
    return nlohmann::json::array({p.sum[0], p.sum[1], p.sum[2], p.denominator});
}

nlohmann::json dual_json(const CellComplex& complex, DualKind kind) {
    nlohmann::json points = nlohmann::json::array(), hexes = nlohmann::json::array();
    if (kind == DualKind::Interior) {
        for (std::size_t c = 0; c < complex.n_cells(); ++c) points.push_back(point_json(cell_centroid(complex, CellHandle(c))));
        for (const auto& hex : interior_dual(complex).mesh.hexes) {
            nlohmann::json h = nlohmann::json::array();
            for (CellHandle c : hex) h.push_back(c.index());
            hexes.push_back(h);
        }
    } else {
        const ClippedDual dual = clipped_dual(complex);
        for (const auto& p : dual.points) points.push_back(point_json(p));
        for (const auto& hex : dual.hexes) hexes.push_back(hex);
    }
    return {{"points", points}, {"hexes", hexes}};
}

}  // namespace

std::string role_of_label(const std::string& label) {
    if (label.find("corner") != std::string::npos) return "corner";  // MR cuts: lid_corner, bend_0_corner
    if (starts_with(label, "lid")) return "lid";
    if (starts_with(label, "bend") || starts_with(label, "tet")) return "bend";
    if (label == "rest") return "rest";
    return "chain";  // p1, p2, q, P1, P1b, B, C, ...: prisms and the cells over crossings
}

std::vector<SceneCell> element_cells(const Element& element) {
    std::vector<SceneCell> out;
    for (const auto& label : element.cell_labels()) out.push_back({element.name, label, role_of_label(label)});
    return out;
}

std::vector<SceneCell> configuration_cells(const ConfigurationComplex& configuration, const ElementLibrary& library,
                                           const std::function<LeafBox(const PlacedLeaf&)>& leaf_box) {
    const CellComplex& complex = configuration.complex;
    std::vector<SceneCell> out(complex.n_cells(), SceneCell{"fine", "hex", "fine"});
    std::vector<std::vector<std::size_t>> in_leaf(configuration.coarse_leaves.size());
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        const RationalPoint p = cell_centroid(complex, CellHandle(c));
        for (std::size_t l = 0; l < configuration.coarse_leaves.size(); ++l) {
            const LeafBox box = leaf_box(configuration.coarse_leaves[l]);
            bool inside = true;  // lo < p < lo + size, scaled by the denominator
            for (int a = 0; a < 3; ++a)
                inside = inside && p.sum[a] > box.lo[a] * p.denominator &&
                         p.sum[a] < (box.lo[a] + box.size) * p.denominator;
            if (inside) in_leaf[l].push_back(c);
        }
    }
    for (std::size_t l = 0; l < in_leaf.size(); ++l) {
        const auto& placement = configuration.coarse_leaves[l].placement;
        const std::string name = placement ? placement->element : "hex";
        std::vector<std::string> labels{"hex"};
        if (placement) labels = library.at(name).cell_labels();
        const bool matched = labels.size() == in_leaf[l].size();  // else: element known, labels not
        for (std::size_t k = 0; k < in_leaf[l].size(); ++k) {
            const std::string label = matched ? labels[k] : "?";
            out[in_leaf[l][k]] = {name, label, placement ? role_of_label(label) : "hex"};
        }
    }
    return out;
}

nlohmann::json histogram_json(const std::map<int, std::size_t>& histogram) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, n] : histogram) j[std::to_string(k)] = n;
    return j;
}

nlohmann::json scene_json(const CellComplex& complex, const std::vector<SceneCell>& cells, DualKind dual) {
    if (cells.size() != complex.n_cells()) throw std::invalid_argument("scene_json: one SceneCell per cell expected");
    nlohmann::json vertices = nlohmann::json::array(), faces = nlohmann::json::array(), out_cells = nlohmann::json::array();
    for (const auto& p : complex.positions()) vertices.push_back({p[0], p[1], p[2]});
    for (std::size_t f = 0; f < complex.n_faces(); ++f) {
        nlohmann::json loop = nlohmann::json::array();
        for (VertexHandle v : complex.face_vertices(FaceHandle(f))) loop.push_back(v.index());
        faces.push_back(loop);
    }
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        nlohmann::json hfs = nlohmann::json::array();
        for (HalfFaceHandle h : complex.cell_halffaces(CellHandle(c))) hfs.push_back({h.face().index(), h.side()});
        out_cells.push_back({{"faces", hfs}, {"role", cells[c].role}, {"element", cells[c].element}, {"label", cells[c].label}});
    }
    return {{"vertices", vertices}, {"faces", faces}, {"cells", out_cells}, {"dual", dual_json(complex, dual)}};
}

}  // namespace dualhex::atlas
