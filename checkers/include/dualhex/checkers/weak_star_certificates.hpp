#pragma once
// Certificates of the weak star runs (proofs/README.md W14): one `star` certificate per
// congruence class of the stars that run_weak_stars and run_weak_root_stars check.
#include <cstddef>
#include <filesystem>

#include "dualhex/checkers/certificate.hpp"

namespace dualhex {

class ElementLibrary;

struct WeakStarCertificates {
    CertificateSet stars, corner;
};

/// Runs run_weak_stars (WeakRule, every parity) and writes into `dir`:
///   stars-AAAA-BBBB.cert   one certificate of kind star per class (domain point 0 0 0: the
///                          whole cells at v, v at the origin), `covers` its members
///   manifest               covers N: the stars in label order (WeakStarLabel: parity, v - g,
///                          configuration, pieces), each once
/// Two stars share a class iff one is the exact image of the other under one of the 48
/// symmetries about v (equal smallest oriented forms: the key is the proof). The class's
/// representative is its member of smallest label. A corner pair W11 checks leaf by leaf
/// has no stars there (it is not enumerated star by star); into `corner_dir`, in the same
/// way, a witness star per quadrant tuple of every such pair (corner_witness_stars; labels:
/// WeakCornerLabel order, covers = the quadrant tuples). std::runtime_error if a star fails.
WeakStarCertificates certify_weak_stars(const ElementLibrary& library, const std::filesystem::path& dir,
                                        const std::filesystem::path& corner_dir, std::size_t per_file = 500);

/// Runs run_weak_root_stars (WeakRule, `Coarse`, then `Mirror`) and writes into `dir`, as
/// certify_weak_stars: every star of a vertex v on the root surface (the inside leaves' cells
/// at v) reflected across its root planes (double_half_window) into a whole star at v, which
/// dualhex checks first (the star checks at v) and proves its own image under each of those
/// reflections; labels: `Coarse`'s stars in order (type, v - g, configuration, pieces), then
/// `Mirror`'s.
CertificateSet certify_weak_root_stars(const ElementLibrary& library, const std::filesystem::path& dir,
                                       std::size_t per_file = 500);

/// Runs run_weak_near_root_stars (WeakRule, `Coarse` near the root surface) and writes into
/// `dir`, as certify_weak_root_stars (a star with root planes through v doubled, the others as
/// they are); labels: WeakNearRootStarLabel order. About 20 times the work of the others.
CertificateSet certify_weak_near_root_stars(const ElementLibrary& library, const std::filesystem::path& dir,
                                            std::size_t per_file = 500);

}  // namespace dualhex
