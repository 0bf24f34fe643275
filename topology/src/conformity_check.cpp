// Check (2): faces are shared by at most two cells, with opposite orientations.
#include <algorithm>

#include "checks.hpp"
#include "dualhex/topology/id_hash_table.hpp"

namespace dualhex::detail {

void check_face_conformity(const Incidence& inc, FaceHandle f, ValidationReport& report) {
    const auto hfs = inc.face_halffaces(f);
    if (hfs.empty())
        report.add({ViolationKind::FaceUnused, {}, {}, f, {}, "face belongs to no cell"});
    else if (hfs.size() > 2)
        report.add({ViolationKind::FaceOvershared, {}, {}, f, {},
                    "face belongs to " + std::to_string(hfs.size()) + " cells"});
    else if (hfs.size() == 2 && hfs[0] == hfs[1])
        report.add({ViolationKind::FaceSameOrientation, {}, {}, f, inc.face_cells(f)[1],
                    "both cells (" + std::to_string(inc.face_cells(f)[0].idx) + ", " +
                        std::to_string(inc.face_cells(f)[1].idx) + ") use side " + std::to_string(hfs[0].side())});
}

void check_duplicate_cells(const CellComplex& k, ValidationReport& report) {
    // Hash the sorted half-face lists; equal lists mean the same oriented cell twice.
    std::vector<std::vector<HalfFaceHandle>> sorted(k.n_cells());
    IdHashTable table(k.n_cells());
    for (std::size_t c = 0; c < k.n_cells(); ++c) {
        const auto hfs = k.cell_halffaces(CellHandle(c));
        sorted[c].assign(hfs.begin(), hfs.end());
        std::sort(sorted[c].begin(), sorted[c].end());
        std::uint64_t hash = mix64(sorted[c].size());
        for (HalfFaceHandle h : sorted[c]) hash = mix64(hash ^ static_cast<std::uint64_t>(h.idx));
        const auto [first, inserted] = table.insert(hash, static_cast<std::int32_t>(c), [&](std::int32_t other) {
            return sorted[static_cast<std::size_t>(other)] == sorted[c];
        });
        if (!inserted)
            report.add({ViolationKind::DuplicateCell, {}, {}, {}, CellHandle(c),
                        "same half-faces as cell " + std::to_string(first)});
    }
}

}  // namespace dualhex::detail
