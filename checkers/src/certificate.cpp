// Certificate producer (format: checkers/include/dualhex/checkers/certificate.hpp,
// proofs/README.md). Untrusted: the claims come from dualhex's topology code; the
// independent checker in proofs/checker decides whether they hold.
#include "dualhex/checkers/certificate.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

const char* to_string(CertificateKind kind) {
    switch (kind) {
        case CertificateKind::Element: return "element";
        case CertificateKind::Configuration: return "configuration";
        case CertificateKind::Installation: return "installation";
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

// The cells of a complex as a set of sets of oriented faces, each face the loop of its
// positions (shifted, modulo period) rotated to start at its smallest point: equal iff two
// complexes are the same up to numbering.
using CanonicalFace = std::vector<LatticePoint>;
std::set<std::vector<CanonicalFace>> canonical_cells(const CellComplex& complex, const LatticePoint& shift,
                                                     std::int64_t period) {
    auto wrap = [&](const LatticePoint& p) {
        LatticePoint q = p + shift;
        for (int a = 0; a < 3; ++a) q[a] = ((q[a] % period) + period) % period;
        return q;
    };
    std::set<std::vector<CanonicalFace>> cells;
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        std::vector<CanonicalFace> faces;
        for (HalfFaceHandle h : complex.cell_halffaces(CellHandle(c))) {
            CanonicalFace loop;
            for (VertexHandle v : complex.halfface_vertices(h)) loop.push_back(wrap(complex.position(v)));
            std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
            faces.push_back(std::move(loop));
        }
        std::sort(faces.begin(), faces.end());
        cells.insert(std::move(faces));
    }
    return cells;
}

}  // namespace

void write_certificate(std::ostream& out, const CellComplex& complex, const CertificateSpec& spec) {
    bool subdivision = spec.subdivision, valences = spec.valences, dual = spec.all_hex_dual;
    if (spec.kind == CertificateKind::Element) subdivision = true;
    if (spec.kind == CertificateKind::Configuration || spec.kind == CertificateKind::Installation)
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
        case CertificateDomain::Type::None: out << "domain none\n"; break;
    }
    out << "vertices " << complex.n_vertices() << '\n';
    for (const LatticePoint& p : complex.positions()) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    out << "faces " << complex.n_faces() << '\n';
    for (std::size_t f = 0; f < complex.n_faces(); ++f) {
        const char* sep = "";
        for (VertexHandle v : complex.face_vertices(FaceHandle(f))) out << sep << v.idx, sep = " ";
        out << '\n';
    }
    out << "cells " << complex.n_cells() << '\n';
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        const char* sep = "";
        for (HalfFaceHandle h : complex.cell_halffaces(CellHandle(c)))
            out << sep << (h.side() ? '-' : '+') << h.face().idx, sep = " ";
        out << '\n';
    }
    const Incidence incidence(complex);
    std::vector<int> interior;
    for (std::size_t v = 0; v < complex.n_vertices(); ++v)
        if (!incidence.is_boundary(VertexHandle(v))) interior.push_back(static_cast<int>(v));
    if (d.type == CertificateDomain::Type::Torus && interior.size() == complex.n_vertices()) {
        out << "interior all\n";
    } else {
        out << "interior " << interior.size();
        for (std::size_t i = 0; i < interior.size(); ++i) out << (i % 16 ? ' ' : '\n') << interior[i];
        out << '\n';
    }
    if (subdivision) out << "claim subdivision\n";
    if (valences) out << "claim valences\n";
    if (dual) out << "claim all-hex-dual\n";
    out << "claim counts " << complex.n_vertices() << ' ' << complex.n_edges() << ' ' << complex.n_faces() << ' '
        << complex.n_cells() << '\n';
    write_histogram(out, "face-sizes", face_size_histogram(complex));
    const auto dual_valences = interior_dual_edge_valence_histogram(complex, incidence);
    if (!dual_valences.empty()) write_histogram(out, "dual-valences", dual_valences);
    out << "claim interior-vertices " << interior.size() << '\n';
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

CertifyResult certify_library(const ElementLibrary& library, const TransitionRule& rule, const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    CertifyResult result;
    auto add = [&](const std::string& file, const std::string& text, std::size_t n, CertificateKind kind) {
        result.files.push_back(write_certificate_file(dir, file, text, n, kind));
        result.certificates += n;
        result.bytes += text.size();
    };
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
    add("elements.cert", text, library.elements().size(), CertificateKind::Element);
    // translation classes: m' = m with octant bits permuted by b -> b ^ t
    auto translate_mask = [](int m, int t) {
        int out = 0;
        for (int b = 0; b < 8; ++b) out |= ((m >> (b ^ t)) & 1) << b;
        return out;
    };
    std::vector<int> representatives;
    for (int m = 0; m < 256; ++m) {
        int rep = m;
        for (int t = 1; t < 8; ++t) rep = std::min(rep, translate_mask(m, t));
        if (rep == m) representatives.push_back(m);
    }
    constexpr std::size_t kPerFile = 12;
    for (std::size_t first = 0; first < representatives.size(); first += kPerFile) {
        const std::size_t last = std::min(first + kPerFile, representatives.size());
        text.clear();
        for (std::size_t r = first; r < last; ++r) {
            const int rep = representatives[r];
            const ConfigurationComplex cc = build_periodic_configuration(static_cast<std::uint8_t>(rep), rule, library);
            const std::int64_t period = 4 * cc.unit;
            const auto canonical = canonical_cells(cc.complex, {0, 0, 0}, period);
            std::set<std::int64_t> members;
            for (int t = 0; t < 8; ++t) {
                const int m = translate_mask(rep, t);
                if (!members.insert(m).second || m == rep) continue;
                // torus(m) shifted by octant cubes t is torus(rep): octant b of m is octant b^t of rep
                const ConfigurationComplex other = build_periodic_configuration(static_cast<std::uint8_t>(m), rule, library);
                const LatticePoint shift{2 * cc.unit * (t & 1), 2 * cc.unit * ((t >> 1) & 1), 2 * cc.unit * ((t >> 2) & 1)};
                if (canonical_cells(other.complex, shift, period) != canonical)
                    throw std::runtime_error("certify: the torus of mask " + std::to_string(m) +
                                             " is not the translate of the torus of mask " + std::to_string(rep));
            }
            CertificateSpec spec;
            spec.name = "configuration-" + std::to_string(rep);
            spec.kind = CertificateKind::Configuration;
            spec.domain = CertificateDomain::torus(period);
            spec.covers.assign(members.begin(), members.end());
            result.configurations_covered += members.size();
            std::string placed;
            for (const PlacedLeaf& leaf : cc.coarse_leaves)
                placed += " " + (leaf.placement ? leaf.placement->element : std::string("hex"));
            spec.comments = {"rule " + rule.name() + ", mask " + std::to_string(rep) + " = " +
                                 format_mask(static_cast<std::uint8_t>(rep)) +
                                 " on the 3-torus of 2x2x2 octant cubes (period 4 coarse leaves = " +
                                 std::to_string(period) + " lattice units)",
                             "coarse leaves:" + placed,
                             "covers: the masks whose tori are this complex translated by octant cubes"};
            text += certificate_to_string(cc.complex, spec);
        }
        char file[64];
        std::snprintf(file, sizeof file, "configurations-%03d-%03d.cert", representatives[first], representatives[last - 1]);
        add(file, text, last - first, CertificateKind::Configuration);
    }
    const std::string manifest = manifest_to_string(result.files, 256);
    std::ofstream out(dir / "manifest", std::ios::binary | std::ios::trunc);
    out << manifest;
    if (!out.flush()) throw std::runtime_error("cannot write " + (dir / "manifest").string());
    return result;
}

}  // namespace dualhex
