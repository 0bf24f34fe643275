// Certificate producer (format: checkers/include/dualhex/checkers/certificate.hpp,
// proofs/README.md). Untrusted: the claims come from dualhex's topology code; the
// independent checker in proofs/checker decides whether they hold.
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/compositional_weak.hpp"
#include "dualhex/checkers/boundary_certificates.hpp"
#include "dualhex/checkers/window_certificates.hpp"
#include "dualhex/checkers/weak_star_certificates.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

const char* to_string(CertificateKind kind) {
    switch (kind) {
        case CertificateKind::Element: return "element";
        case CertificateKind::Configuration: return "configuration";
        case CertificateKind::Installation: return "installation";
        case CertificateKind::Star: return "star";
        case CertificateKind::Histogram: return "histogram";
    }
    return "?";
}

namespace {

void write_histogram(std::ostream& out, const char* claim, const std::map<int, std::size_t>& h) {
    out << "claim " << claim;
    for (const auto& [k, n] : h) out << ' ' << k << ':' << n;
    out << '\n';
}

}  // namespace

void write_certificate(std::ostream& out, const CellComplex& complex, const CertificateSpec& spec) {
    bool subdivision = spec.subdivision, valences = spec.valences, dual = spec.all_hex_dual;
    if (spec.kind == CertificateKind::Element) subdivision = true;
    if (spec.kind == CertificateKind::Configuration || spec.kind == CertificateKind::Installation ||
        spec.kind == CertificateKind::Star)
        subdivision = valences = dual = true;
    if (spec.name.empty() || spec.name.find_first_of(" \t\n#") != std::string::npos)
        throw std::invalid_argument("certificate name must be one word: '" + spec.name + "'");

    out << "dualhex-certificate " << kCertificateFormatVersion << '\n';
    for (const std::string& c : spec.comments) out << "# " << c << '\n';
    out << "name " << spec.name << '\n' << "kind " << to_string(spec.kind) << '\n';
    const CertificateDomain& d = spec.domain;
    switch (d.type) {
        case CertificateDomain::Type::Box:
            out << "domain box " << d.lo.x << ' ' << d.lo.y << ' ' << d.lo.z << ' ' << d.hi.x << ' ' << d.hi.y << ' '
                << d.hi.z << '\n';
            break;
        case CertificateDomain::Type::Torus: out << "domain torus " << d.period << '\n'; break;
        case CertificateDomain::Type::Point: out << "domain point " << d.lo.x << ' ' << d.lo.y << ' ' << d.lo.z << '\n'; break;
    }
    for (const LatticePoint& p : complex.positions()) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (std::size_t f = 0; f < complex.n_faces(); ++f) {
        out << 'f';
        for (VertexHandle v : complex.face_vertices(FaceHandle(f))) out << ' ' << v.idx;
        out << '\n';
    }
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        out << 'c';
        for (HalfFaceHandle h : complex.cell_halffaces(CellHandle(c))) out << ' ' << (h.side() ? '-' : '+') << h.face().idx;
        out << '\n';
    }
    const Incidence incidence(complex);
    std::size_t interior = 0;
    for (std::size_t v = 0; v < complex.n_vertices(); ++v) interior += !incidence.is_boundary(VertexHandle(v));
    if (subdivision) out << "claim subdivision\n";
    if (valences) out << "claim valences\n";
    if (dual) out << "claim all-hex-dual\n";
    out << "claim counts " << complex.n_vertices() << ' ' << complex.n_edges() << ' ' << complex.n_faces() << ' '
        << complex.n_cells() << '\n';
    write_histogram(out, "face-sizes", face_size_histogram(complex));
    const auto dual_valences = interior_dual_edge_valence_histogram(complex, incidence);
    if (!dual_valences.empty()) write_histogram(out, "dual-valences", dual_valences);
    out << "claim interior-vertices " << interior << '\n';
    if (!spec.covers.empty()) {
        out << "covers";
        for (std::int64_t x : spec.covers) out << ' ' << x;
        out << '\n';
    }
    out << "end\n";
}

std::string certificate_to_string(const CellComplex& complex, const CertificateSpec& spec) {
    std::ostringstream os;
    write_certificate(os, complex, spec);
    return os.str();
}

std::uint64_t fnv1a64(std::string_view bytes) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return h;
}

std::string fnv1a64_hex(std::string_view bytes) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(bytes)));
    return hex;
}

std::string manifest_to_string(const std::vector<ManifestEntry>& entries, std::int64_t covers) {
    std::ostringstream os;
    std::size_t total = 0;
    for (const ManifestEntry& e : entries) total += e.certificates;
    os << "dualhex-manifest 1\n"
       << "# Re-check: dualhex-proof-checker <this file>   (format: proofs/README.md)\n"
       << "total " << total << '\n';
    if (covers >= 0) os << "covers " << covers << '\n';
    for (const ManifestEntry& e : entries)
        os << "file " << e.file << ' ' << e.certificates << ' ' << to_string(e.kind) << " fnv1a64 " << e.hash << '\n';
    return os.str();
}

ManifestEntry write_certificate_file(const std::filesystem::path& dir, const std::string& file, const std::string& text,
                                     std::size_t certificates, CertificateKind kind) {
    std::ofstream out(dir / file, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + (dir / file).string());
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + (dir / file).string());
    return {file, certificates, kind, fnv1a64_hex(text)};
}

CertificateSet::CertificateSet(std::filesystem::path dir, std::int64_t covers_labels)
    : directory(std::move(dir)), covers(covers_labels) {
    std::filesystem::create_directories(directory);
}

void CertificateSet::add(const std::string& file, const std::string& text, std::size_t n, CertificateKind kind) {
    files.push_back(write_certificate_file(directory, file, text, n, kind));
    certificates += n;
    bytes += text.size();
}

void CertificateSet::add_ranges(const Ranges& ranges, std::size_t n, CertificateKind kind,
                                const std::function<std::string(std::size_t)>& certificate,
                                const std::function<std::size_t(std::size_t)>& name) {
    std::string text;
    std::size_t first = 0;
    for (std::size_t r = 0; r < n; ++r) {
        text += certificate(r);
        if (r + 1 < n && r + 1 - first < ranges.max_count && text.size() < ranges.max_bytes) continue;
        char file[96];
        std::snprintf(file, sizeof file, "%s-%0*zu-%0*zu.cert", ranges.prefix.c_str(), ranges.digits, name(first),
                      ranges.digits, name(r));
        add(file, text, r + 1 - first, kind);
        text.clear();
        first = r + 1;
    }
}

void CertificateSet::write_manifest() const {
    std::ofstream out(directory / "manifest", std::ios::binary | std::ios::trunc);
    out << manifest_to_string(files, covers);
    if (!out.flush()) throw std::runtime_error("cannot write " + (directory / "manifest").string());
}

std::size_t CertifyResult::certificates() const {
    std::size_t n = 0;
    for (const CertificateSet& s : sets) n += s.certificates;
    return n;
}

std::size_t CertifyResult::bytes() const {
    std::size_t n = 0;
    for (const CertificateSet& s : sets) n += s.bytes;
    return n;
}

CertifyResult certify_library(const ElementLibrary& library, const std::filesystem::path& dir, const Progress& progress,
                              bool near_root_stars) {
    CertifyResult result;
    result.sets.push_back(certify_strong(library, StrongRule{}, dir, progress));
    result.sets.push_back(certify_weak(library, WeakRule{}, dir / "weak", progress));
    report_progress(progress, "variants", 0, 1);
    result.sets.push_back(certify_variants(library, dir / "variants"));
    result.sets.push_back(certify_windows(StrongRule{}, library, dir / "windows", 100, progress));
    report_progress(progress, "boundary windows", 0, 1);
    result.sets.push_back(certify_boundary_windows(StrongRule{}, library, dir / "boundary"));
    result.sets.push_back(certify_spread_grids(library, dir / "weak_spread"));
    report_progress(progress, "weak stars", 0, 1);
    auto [stars, corner] = certify_weak_stars(library, dir / "weak_stars", dir / "weak_corner_stars");
    result.sets.push_back(std::move(stars));
    result.sets.push_back(std::move(corner));
    report_progress(progress, "weak root stars", 0, 1);
    result.sets.push_back(certify_weak_root_stars(library, dir / "weak_root_stars"));
    if (near_root_stars) {
        report_progress(progress, "weak near-root stars", 0, 1);
        result.sets.push_back(certify_weak_near_root_stars(library, dir / "weak_near_root_stars"));
    }
    return result;
}

}  // namespace dualhex
