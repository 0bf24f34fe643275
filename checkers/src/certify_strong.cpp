// certify_strong: the elements and the 256 strong tori as certificates (certificate.hpp).

#include "dualhex/install/element_templates.hpp"
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/torus_classes.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex {

namespace {

std::string element_certificates(const ElementLibrary& library) {
    std::string text;
    for (const Element& e : library.elements()) {
        CertificateSpec spec;
        spec.name = e.name;
        spec.kind = CertificateKind::Element;
        spec.domain = CertificateDomain::box({0, 0, 0}, {e.leaf(), e.leaf(), e.leaf()});
        spec.comments = {"element " + e.name + " (" + e.file.filename().string() + "): a subdivision of its leaf [0," +
                         std::to_string(e.leaf()) + "]^3"};
        text += certificate_to_string(e.complex, spec);
    }
    return text;
}

std::string torus_certificate(const TorusClass& c, const TransitionRule& rule, const ElementLibrary& library) {
    const std::uint8_t rep = static_cast<std::uint8_t>(c.representative);
    const ConfigurationComplex cc = build_periodic_configuration(rep, rule, library);
    const std::int64_t period = 4 * cc.unit;
    require_closed_torus(cc.complex, period / 2, "the torus of mask " + std::to_string(rep));
    CertificateSpec spec;
    spec.name = "configuration-" + std::to_string(rep);
    spec.kind = CertificateKind::Configuration;
    spec.domain = CertificateDomain::torus(period);
    for (const auto& [mask, motion] : c.members) spec.covers.push_back(static_cast<std::int64_t>(mask));
    std::string placed;
    for (const PlacedLeaf& leaf : cc.coarse_leaves)
        placed += " " + (leaf.placement ? leaf.placement->element : std::string("hex"));
    spec.comments = {"rule " + rule.name() + ", mask " + std::to_string(rep) + " = " + format_mask(rep) +
                         " on the 3-torus of 2x2x2 octant cubes (period 4 coarse leaves = " + std::to_string(period) +
                         " lattice units)",
                     "coarse leaves:" + placed,
                     "covers: the masks whose tori are this complex translated by octant cubes"};
    return certificate_to_string(cc.complex, spec);
}

}  // namespace

CertificateSet certify_strong(const ElementLibrary& library, const TransitionRule& rule, const std::filesystem::path& dir,
                              const Progress& progress) {
    CertificateSet set(dir, 256);
    set.add("elements.cert", element_certificates(library), library.elements().size(), CertificateKind::Element);
    // a motion moves octant b of the torus to octant apply_octant(b): mask bits likewise
    const auto image = [](std::size_t mask, const TorusMotion& m) {
        std::size_t out = 0;
        for (int b = 0; b < 8; ++b) out |= ((mask >> b) & 1u) << m.apply_octant(b);
        return out;
    };
    const auto build = [&](std::size_t mask) {
        return build_periodic_configuration(static_cast<std::uint8_t>(mask), rule, library).complex;
    };
    const std::int64_t octant = 2 * detail::common_unit(library);
    const std::vector<TorusClass> classes = torus_classes(256, image, build, torus_translations(), octant, progress, "strong tori");
    set.add_ranges({.prefix = "configurations", .digits = 3, .max_count = 12}, classes.size(),
                   CertificateKind::Configuration,
                   [&](std::size_t r) { return torus_certificate(classes[r], rule, library); },
                   [&](std::size_t r) { return classes[r].representative; });
    set.write_manifest();
    return set;
}

}  // namespace dualhex
