#pragma once
// Certificates (proofs/README.md): the producer side. A certificate lists a complex
// explicitly (vertices with integer coordinates, faces as vertex loops, cells as signed
// face lists, the interior vertices) and its claims; proofs/checker re-checks it without
// any dualhex code. Everything claimed here (counts, histograms, the interior set) is
// computed from the complex by dualhex's topology code; whether it is TRUE is for the
// independent checker to decide.
//
// Format version 2:
//   dualhex-certificate 2
//   name NAME
//   kind element|configuration|installation|star|histogram
//   domain box X0 Y0 Z0 X1 Y1 Z1 | domain torus P | domain point X Y Z (a star's vertex)
//   v x y z         one line per vertex               (vertex ids 0, 1, ... in order)
//   f v0 v1 v2 ...  one line per face: a vertex loop  (face ids 0, 1, ...)
//   c +f -g ...     one line per cell: signed faces   (+f: face f's loop as written is
//                                                     counter-clockwise seen from outside)
//   covers L1 L2 ...   (optional) the labels this certificate stands for
//   claim subdivision | valences | all-hex-dual | counts V E F C |
//         face-sizes K:N ... | dual-valences K:N ... | interior-vertices N
//   end
// (interior vertices are those on no face of one cell: the checker computes them.)
// A file may hold several certificates; a manifest lists the files:
//   dualhex-manifest 1
//   total N
//   covers N           (optional) the certificates' covers are exactly 0..N-1, once each
//   file NAME COUNT KIND fnv1a64 HEX16
#include <cstdint>
#include <functional>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/progress.hpp"

namespace dualhex {

/// The standalone checker accepts coordinates, box bounds and periods in [-2^19, 2^19] only
/// (its overflow proof: proofs/README.md, "Bounds"); a producer must not write beyond.
inline constexpr std::int64_t kCertificateMaxCoordinate = std::int64_t{1} << 19;
/// The deepest grid level whose installation (box [0, unit << level]) can be certified.
[[nodiscard]] constexpr int max_certifiable_level(std::int64_t unit) {
    int level = 0;
    while ((unit << (level + 1)) <= kCertificateMaxCoordinate) ++level;
    return level;
}


class ElementLibrary;
class TransitionRule;

inline constexpr int kCertificateFormatVersion = 2;

enum class CertificateKind { Element, Configuration, Installation, Star, Histogram };
[[nodiscard]] const char* to_string(CertificateKind kind);

struct CertificateDomain {
    enum class Type { Box, Torus, Point } type = Type::Box;
    LatticePoint lo, hi;     ///< Box: the box [lo, hi]; Point: the star's point, lo
    std::int64_t period = 0; ///< Torus: vertex coordinates are residues modulo period (all axes)

    [[nodiscard]] static CertificateDomain box(const LatticePoint& lo, const LatticePoint& hi) {
        return {Type::Box, lo, hi, 0};
    }
    [[nodiscard]] static CertificateDomain torus(std::int64_t period) { return {Type::Torus, {}, {}, period}; }
    [[nodiscard]] static CertificateDomain point(const LatticePoint& p) { return {Type::Point, p, p, 0}; }
};

struct CertificateSpec {
    std::string name;  ///< one word, unique within a manifest
    CertificateKind kind = CertificateKind::Histogram;
    CertificateDomain domain;
    /// The claims beyond counts / histograms / interior count (always written). The kind
    /// fixes the minimum: element = subdivision; configuration, installation and star =
    /// subdivision + valences + all-hex-dual (set automatically).
    bool subdivision = false, valences = false, all_hex_dual = false;
    std::vector<std::string> comments;  ///< '#' lines after the header
    /// Labels this certificate stands for (`covers` line; e.g. the configuration masks whose
    /// tori are this complex up to translation). Empty: no line.
    std::vector<std::int64_t> covers;
};

/// Writes one certificate for `complex` (ids as in the complex: vertex k, face k, cell k).
void write_certificate(std::ostream& out, const CellComplex& complex, const CertificateSpec& spec);
[[nodiscard]] std::string certificate_to_string(const CellComplex& complex, const CertificateSpec& spec);

/// FNV-1a 64 over the bytes (the manifest's hash; the checker implements it too).
[[nodiscard]] std::uint64_t fnv1a64(std::string_view bytes);
[[nodiscard]] std::string fnv1a64_hex(std::string_view bytes);  ///< 16 lower-case hex digits

struct ManifestEntry {
    std::string file;  ///< relative to the manifest's directory
    std::size_t certificates = 0;
    CertificateKind kind = CertificateKind::Histogram;
    std::string hash;  ///< fnv1a64_hex of the file's bytes
};
/// covers < 0: no `covers` line.
[[nodiscard]] std::string manifest_to_string(const std::vector<ManifestEntry>& entries, std::int64_t covers = -1);

/// Writes `text` to dir/file and returns its manifest entry.
ManifestEntry write_certificate_file(const std::filesystem::path& dir, const std::string& file, const std::string& text,
                                     std::size_t certificates, CertificateKind kind);

/// One certificate directory with its own manifest (its own label space for `covers`).
struct CertificateSet {
    std::filesystem::path directory;
    std::vector<ManifestEntry> files;  ///< in manifest order
    std::size_t certificates = 0, bytes = 0;
    std::int64_t covers = -1;  ///< the manifest's `covers N`: labels 0..N-1 (-1: no line)

    /// Creates the directory if needed.
    explicit CertificateSet(std::filesystem::path dir, std::int64_t covers = -1);
    /// Writes `text` (n certificates of one kind) to directory/file and records it.
    void add(const std::string& file, const std::string& text, std::size_t n, CertificateKind kind);
    /// How add_ranges splits certificates into files: a file is closed after `max_count`
    /// certificates or once its text reaches `max_bytes`, and named
    /// "PREFIX-AAA-BBB.cert" with AAA, BBB = name(first), name(last) in `digits` digits.
    struct Ranges {
        std::string prefix;
        int digits = 3;
        std::size_t max_count = SIZE_MAX, max_bytes = SIZE_MAX;
    };
    /// Writes certificates 0..n-1 (certificate(i): its text) into range files.
    void add_ranges(const Ranges& ranges, std::size_t n, CertificateKind kind,
                    const std::function<std::string(std::size_t)>& certificate,
                    const std::function<std::size_t(std::size_t)>& name);
    /// Writes directory/manifest (total, covers, the files with their hashes).
    void write_manifest() const;
};

/// Elements and strong tori, into `dir` (what proofs/certificates/ holds):
///   elements.cert                   one element certificate per library element
///   configurations-AAA-BBB.cert     periodic tori (build_periodic_configuration), 12 per file
///   manifest                        covers 256 (the masks)
/// Translating the torus by octant cubes turns the torus of mask m into the torus of another
/// mask: the 256 tori are 46 complexes up to translation. One certificate is written per
/// translation class (the smallest mask; `covers` lists the class) after checking, for every
/// other mask, that its torus as built IS the translate (torus_classes.hpp);
/// std::runtime_error if not (then the rule is not translation invariant).
/// `progress` (optional): stage "strong tori", the masks classified of 256.
CertificateSet certify_strong(const ElementLibrary& library, const TransitionRule& rule, const std::filesystem::path& dir,
                              const Progress& progress = {});

/// The 487 weakly balanced assignments (weak_configurations() order = the labels), each on
/// its torus (build_periodic_levels with 2x2x2 octant cubes), into `dir`:
///   configurations-AAA-BBB.cert     one certificate per class under the 384 torus motions
///                                   (cube symmetries and octant shifts; the smallest label
///                                   represents it; `covers` lists the class and a comment
///                                   the motion producing each member, checked as for
///                                   certify_strong)
///   manifest                        covers 487
/// std::runtime_error if a torus is not closed with every vertex interior and in the period.
/// `progress` (optional): stage "weak tori", the labels classified of 487.
CertificateSet certify_weak(const ElementLibrary& library, const TransitionRule& rule, const std::filesystem::path& dir,
                            const Progress& progress = {});

/// The 14 crossing variants (schemes/variants.hpp; labels in `dualhex variants` order: flat
/// x z, concave edge LL LU UL UU, concave corner XXY .. ZYZ), into `dir`:
///   elements.cert                   each variant as an element of [0,12]^3
///   configurations.cert             each variant installed on its region's torus (as
///                                   variants_report.hpp installs it), covers its label
///   histograms.cert                 (only if some variant fails dualhex's own checks) the
///                                   same as kind histogram: counts and histograms only
///   manifest                        covers 14
/// `library`: the shipped elements the variants are added to (its directory is reloaded).
CertificateSet certify_variants(const ElementLibrary& library, const std::filesystem::path& dir);

/// Everything `dualhex certify` writes: certify_strong (StrongRule) into `dir`,
/// certify_weak (WeakRule) into dir/weak, certify_variants into dir/variants, certify_windows
/// (StrongRule, window_certificates.hpp) into dir/windows, certify_boundary_windows
/// (StrongRule, boundary_certificates.hpp) into dir/boundary, certify_spread_grids
/// (WeakRule, compositional_weak.hpp) into dir/weak_spread, certify_weak_stars and
/// certify_weak_root_stars (weak_star_certificates.hpp) into dir/weak_stars,
/// dir/weak_corner_stars and dir/weak_root_stars; with `near_root_stars` also
/// certify_weak_near_root_stars into
/// dir/weak_near_root_stars (not shipped: about 70 MB, minutes and gigabytes; see there).
struct CertifyResult {
    std::vector<CertificateSet> sets;
    [[nodiscard]] std::size_t certificates() const;
    [[nodiscard]] std::size_t bytes() const;
};
/// `progress` (optional) sees each part's stages in turn (the windows: checked of all).
CertifyResult certify_library(const ElementLibrary& library, const std::filesystem::path& dir,
                              const Progress& progress = {}, bool near_root_stars = false);

}  // namespace dualhex
