// certify_variants: the 14 crossing variants, each as an element and installed on its
// region's torus, as certificates (certificate.hpp, variants_report.hpp).
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/variants_report.hpp"
#include "dualhex/schemes/signature_rule.hpp"

namespace dualhex {

namespace {

constexpr const char* kOrder =
    "labels in `dualhex variants` order: flat x z, concave edge LL LU UL UU, "
    "concave corner XXY XXZ XYY XYZ ZXY ZXZ ZYY ZYZ";

std::string element_certificate(const Element& e, const variants::Variant& v) {
    CertificateSpec spec;
    spec.name = v.name;
    spec.kind = CertificateKind::Element;
    spec.domain = CertificateDomain::box({0, 0, 0}, {e.leaf(), e.leaf(), e.leaf()});
    spec.comments = {"crossing variant " + v.name + " (" + variants::to_string(v.region) + ", assignment " +
                     v.assignment + "): a subdivision of its leaf [0," + std::to_string(e.leaf()) + "]^3"};
    return certificate_to_string(e.complex, spec);
}

// The variant installed as `dualhex variants` installs it; kind configuration if dualhex's own
// check passes (then valences and the all-hex dual are claimed), histogram otherwise.
std::string torus_certificate(const variants::Variant& v, const ElementLibrary& library, std::int64_t label, bool& ok) {
    const std::uint8_t mask = variants::region_mask(v.region);
    const StrongRule strong;
    const variants::SubstitutingRule rule(strong, variants::region_element(v.region), v.name);
    const ConfigurationComplex cc = build_periodic_configuration(mask, rule, library);
    ok = check_periodic_configuration(mask, rule, library).ok();
    CertificateSpec spec;
    spec.name = "torus-" + v.name;
    spec.kind = ok ? CertificateKind::Configuration : CertificateKind::Histogram;
    spec.domain = CertificateDomain::torus(4 * cc.unit);
    spec.covers = {label};
    spec.comments = {"crossing variant " + v.name + " (" + variants::to_string(v.region) + ", assignment " +
                         v.assignment + ") placed wherever rule strong places " + variants::region_element(v.region) +
                         " (same symmetry),",
                     "on the 3-torus of mask " + format_mask(mask) + " (period " + std::to_string(4 * cc.unit) +
                         " lattice units): its histograms are the variant's",
                     std::string("covers: ") + kOrder};
    return certificate_to_string(cc.complex, spec);
}

}  // namespace

CertificateSet certify_variants(const ElementLibrary& shipped, const std::filesystem::path& dir) {
    using variants::Region;
    std::string elements, tori, histograms;
    std::size_t n_tori = 0, n_histograms = 0;
    std::int64_t label = 0;
    for (Region region : {Region::Flat, Region::ConcaveEdge, Region::ConcaveCorner}) {
        const std::vector<variants::Variant> built = variants::region_variants(region);
        std::vector<ElementData> data;
        for (const variants::Variant& v : built) data.push_back(v.element_data());
        const ElementLibrary library = variants::library_with(data, shipped.directory());  // strict: valid elements
        for (const variants::Variant& v : built) {
            elements += element_certificate(library.at(v.name), v);
            bool ok = false;
            const std::string text = torus_certificate(v, library, label++, ok);
            (ok ? tori : histograms) += text;
            ++(ok ? n_tori : n_histograms);
        }
    }
    CertificateSet set(dir, label);
    set.add("elements.cert", elements, static_cast<std::size_t>(label), CertificateKind::Element);
    if (n_tori) set.add("configurations.cert", tori, n_tori, CertificateKind::Configuration);
    if (n_histograms) set.add("histograms.cert", histograms, n_histograms, CertificateKind::Histogram);
    set.write_manifest();
    return set;
}

}  // namespace dualhex
