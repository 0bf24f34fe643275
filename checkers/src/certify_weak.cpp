// certify_weak: the 487 weakly balanced tori as certificates, one per class under the 384
// torus motions (certificate.hpp, torus_classes.hpp).
#include <algorithm>
#include <map>

#include "dualhex/install/element_templates.hpp"
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/torus_classes.hpp"
#include "dualhex/checkers/weak_exhaustive.hpp"

namespace dualhex {

namespace {

std::string levels_string(const LevelAssignment& levels) {
    std::string s;
    for (std::uint8_t l : levels) s.append(s.empty() ? "" : " ").append(std::to_string(int(l)));
    return s;
}

std::vector<std::string> weak_comments(const TorusClass& c, const std::vector<LevelAssignment>& all,
                                       const ConfigurationComplex& cc, const std::string& rule, std::int64_t octant) {
    std::map<std::string, std::size_t> elements;
    for (const PlacedLeaf& leaf : cc.coarse_leaves) ++elements[leaf.placement ? leaf.placement->element : "hex"];
    std::string placed;
    for (const auto& [name, n] : elements) placed += " " + name + ":" + std::to_string(n);
    std::vector<std::string> out{
        "rule " + rule + ", weak assignment " + std::to_string(c.representative) + ": levels " +
            levels_string(all[c.representative]) + " (octant cubes 0..7, cube (x,y,z) = x + 2y + 4z)",
        "on the 3-torus of 2x2x2 octant cubes (period " + std::to_string(2 * octant) +
            " lattice units; leaves of level 0, 1, 2: " + std::to_string(octant / 2) + ", " + std::to_string(octant / 4) +
            ", " + std::to_string(octant / 8) + ")",
        "coarse leaves (levels 0 and 1):" + placed + "; fine hexes (level 2): " + std::to_string(cc.fine_hexes),
        "covers: the assignments (weak_configurations() order) whose tori are this complex moved by"};
    for (std::size_t i = 1; i < c.members.size(); ++i)
        out.push_back("  " + std::to_string(c.members[i].first) + " (levels " + levels_string(all[c.members[i].first]) +
                      "): " + c.members[i].second.to_string());
    return out;
}

std::string weak_certificate(const TorusClass& c, const std::vector<LevelAssignment>& all, const TransitionRule& rule,
                             const ElementLibrary& library, std::int64_t octant) {
    const ConfigurationComplex cc = build_periodic_levels(torus_levels(all[c.representative]), 2, rule, library);
    require_closed_torus(cc.complex, octant, "the torus of weak assignment " + std::to_string(c.representative));
    CertificateSpec spec;
    spec.name = "weak-" + std::to_string(c.representative);
    spec.kind = CertificateKind::Configuration;
    spec.domain = CertificateDomain::torus(2 * octant);
    for (const auto& [label, motion] : c.members) spec.covers.push_back(static_cast<std::int64_t>(label));
    std::sort(spec.covers.begin(), spec.covers.end());
    spec.comments = weak_comments(c, all, cc, rule.name(), octant);
    return certificate_to_string(cc.complex, spec);
}

}  // namespace

CertificateSet certify_weak(const ElementLibrary& library, const TransitionRule& rule, const std::filesystem::path& dir,
                            const Progress& progress) {
    const std::vector<LevelAssignment> all = weak_configurations();
    std::map<LevelAssignment, std::size_t> label;
    for (std::size_t i = 0; i < all.size(); ++i) label[all[i]] = i;
    const auto image = [&](std::size_t i, const TorusMotion& m) {
        LevelAssignment moved{};
        for (int b = 0; b < 8; ++b) moved[static_cast<std::size_t>(m.apply_octant(b))] = all[i][static_cast<std::size_t>(b)];
        return label.at(moved);
    };
    const auto build = [&](std::size_t i) { return build_periodic_levels(torus_levels(all[i]), 2, rule, library).complex; };
    const std::int64_t octant = 4 * detail::common_unit(library);
    const std::vector<TorusClass> classes = torus_classes(all.size(), image, build, torus_motions(), octant, progress, "weak tori");

    CertificateSet set(dir, static_cast<std::int64_t>(all.size()));
    set.add_ranges({.prefix = "configurations", .digits = 3, .max_bytes = 512 * 1024}, classes.size(),
                   CertificateKind::Configuration,
                   [&](std::size_t r) { return weak_certificate(classes[r], all, rule, library, octant); },
                   [&](std::size_t r) { return classes[r].representative; });
    set.write_manifest();
    return set;
}

}  // namespace dualhex
