#pragma once
// The certificates of the compositional windows (compositional.hpp, proofs/README.md).
#include <filesystem>

#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/compositional.hpp"

namespace dualhex {

/// The windows' certificates (what proofs/certificates/windows/ holds), into `dir`:
///   windows-AAAA-BBBB.cert   one `installation` certificate (box [-U, U]^3) per congruence
///                            class of windows under the 48 symmetries about g, `per_file`
///                            per file; `covers` lists the enumeration indices of its members
///   manifest                 covers = the number of windows enumerated
/// Every member is checked to be the exact image of its class's representative; throws
/// std::runtime_error if one is not, or if any window fails. `progress` (optional): as
/// run_compositional's.
CertificateSet certify_windows(const TransitionRule& rule, const ElementLibrary& library,
                               const std::filesystem::path& dir, std::size_t per_file = 100,
                               const Progress& progress = {});

}  // namespace dualhex
