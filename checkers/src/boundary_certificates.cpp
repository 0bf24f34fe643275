// Certificates of the root boundary (boundary_certificates.hpp): the doubled half windows,
// one `installation` certificate per congruence class.
#include "dualhex/checkers/boundary_certificates.hpp"

#include <map>
#include <stdexcept>

#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/cube_symmetry.hpp"
#include "congruence_check.hpp"
#include "window_check.hpp"

namespace dualhex {
namespace {

struct Class {
    std::string witness;
    CellComplex complex;
    std::vector<std::int64_t> members;
};

}  // namespace

bool symmetric_across_root_planes(const CellComplex& k, const RootSides& sides) {
    const detail::OrientedForm self = detail::oriented_form(k, [](const LatticePoint& p) { return p; }, false);
    for (int a = 0; a < 3; ++a) {
        if (sides[static_cast<std::size_t>(a)] == 0) continue;
        const auto reflect = [a](LatticePoint p) {
            p[a] = -p[a];
            return p;
        };
        if (self.empty() || detail::oriented_form(k, reflect, true) != self) return false;
    }
    return true;
}

CellComplex double_half_window(const CellComplex& half, const RootSides& sides) {
    unsigned axes = 0;
    for (unsigned a = 0; a < 3; ++a) axes |= sides[a] != 0 ? 1U << a : 0U;
    ComplexBuilder builder;
    std::vector<VertexHandle> loop;
    std::vector<HalfFaceHandle> hfs;
    for (unsigned r = 0; r < 8; ++r) {  // every subset of the root axes: one reflected copy
        if (r & ~axes) continue;
        const bool odd = ((r & 1U) + ((r >> 1) & 1U) + ((r >> 2) & 1U)) % 2 == 1;
        const auto move = [&](const LatticePoint& p) {
            LatticePoint q = p;
            for (int a = 0; a < 3; ++a)
                if ((r >> a) & 1U) q[a] = -q[a];
            return q;
        };
        for (std::size_t c = 0; c < half.n_cells(); ++c) {
            hfs.clear();
            for (HalfFaceHandle h : half.cell_halffaces(CellHandle(c))) {
                // the half-face's outward loop; a reflection turns it inward, so reverse it
                const auto face = half.face_vertices(h.face());
                loop.clear();
                for (VertexHandle v : face) loop.push_back(builder.add_vertex(move(half.position(v))));
                if ((h.side() == 1) != odd) std::reverse(loop.begin(), loop.end());
                hfs.push_back(builder.add_face(loop));
            }
            builder.add_cell(hfs);
        }
    }
    return std::move(builder).build();
}

CertificateSet certify_boundary_windows(const TransitionRule& rule, const ElementLibrary& library,
                                        const std::filesystem::path& dir, std::size_t per_file) {
    std::map<detail::OrientedForm, std::size_t> class_of;
    std::vector<Class> classes;
    std::int64_t label = 0, unit = 0;
    BoundaryOptions options;
    options.on_window = [&](const BoundaryWindowView& w) {
        if (!w.passed) throw std::runtime_error("certify_boundary_windows: window " + w.witness + " fails");
        unit = w.unit;
        CellComplex doubled = double_half_window(*w.half, w.type->sides);
        const ConfigurationReport r = detail::check_window(0, w.unit, [&] {
            ConfigurationComplex c;
            c.unit = w.unit;
            c.complex = doubled;
            return c;
        });
        if (!r.ok()) throw std::runtime_error("certify_boundary_windows: doubled window " + w.witness + " fails: " + r.summary());
        if (!symmetric_across_root_planes(doubled, w.type->sides))
            throw std::runtime_error("certify_boundary_windows: doubled window " + w.witness + " is not symmetric");
        detail::OrientedForm key = detail::congruence_key(doubled);
        if (key.empty()) throw std::runtime_error("certify_boundary_windows: a window has no lattice form");
        const auto [it, fresh] = class_of.emplace(std::move(key), classes.size());
        if (fresh) classes.push_back({w.witness, std::move(doubled), {}});
        classes[it->second].members.push_back(label++);
    };
    for (BoundaryPolicy policy : {BoundaryPolicy::Coarse, BoundaryPolicy::Mirror})
        if (!run_compositional_boundary(rule, library, policy, options).all_passed())
            throw std::runtime_error("certify_boundary_windows: the enumeration does not pass");

    CertificateSet set(dir, label);
    const auto certificate = [&](std::size_t k) {
        const Class& c = classes[k];
        CertificateSpec spec;
        spec.name = "boundary-" + std::to_string(k);
        spec.kind = CertificateKind::Installation;
        spec.domain = CertificateDomain::box({-unit, -unit, -unit}, {unit, unit, unit});
        spec.comments = {"a root-boundary half window (inside leaves of B(g)) reflected across its root planes "
                         "(proofs/README.md, \"Root boundary\")",
                         "representative: " + c.witness,
                         "covers: the " + std::to_string(c.members.size()) +
                             " doubled windows (coarse: labels from 0, mirror: after them) congruent to it"};
        spec.covers = c.members;
        return certificate_to_string(c.complex, spec);
    };
    set.add_ranges({.prefix = "boundary", .digits = 4, .max_count = per_file}, classes.size(), CertificateKind::Installation,
                   certificate, [](std::size_t k) { return k; });
    set.write_manifest();
    return set;
}

}  // namespace dualhex
