#pragma once
// Certificates of the root boundary (compositional_boundary.hpp; proofs/README.md, "Root
// boundary"), in the existing `installation` kind: every half window, reflected across its
// root planes (2^k copies, loops reversed for each reflection), is a full window
// [-U, U]^3 whose vertices on the root planes are interior. The checker proves them valid
// there; the doubled complex being symmetric under those reflections by construction, the
// half is then valid as a boundary (the argument in proofs/README.md).
#include <filesystem>

#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/compositional_boundary.hpp"

namespace dualhex {

/// The half window reflected across the root planes of `sides` (the planes x_a = 0).
[[nodiscard]] CellComplex double_half_window(const CellComplex& half, const RootSides& sides);
/// True iff the complex is its own image (exact oriented forms) under the reflection across
/// each root plane of `sides`: what the argument from a doubled complex back to its half
/// needs (proofs/README.md, "Root boundary" step 6); the checker does not check it.
[[nodiscard]] bool symmetric_across_root_planes(const CellComplex& complex, const RootSides& sides);

/// Into `dir`: boundary-AAAA-BBBB.cert, one `installation` certificate (box [-U, U]^3) per
/// congruence class (48 symmetries about g) of the doubled half windows of the `Coarse`
/// (labels 0..n-1) and `Mirror` (labels n..) enumerations; manifest covers = their number.
/// Every doubled window is checked by dualhex first (vertices strictly inside the box) and
/// every member proved the exact image of its representative; throws std::runtime_error if
/// one is not, or if any window fails.
CertificateSet certify_boundary_windows(const TransitionRule& rule, const ElementLibrary& library,
                                        const std::filesystem::path& dir, std::size_t per_file = 100);

}  // namespace dualhex
