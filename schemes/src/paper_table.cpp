#include "dualhex/schemes/paper_table.hpp"

#include <sstream>

namespace dualhex {

namespace {
// Livesu, Pitzalis, Cherchi, "Optimal Dual Schemes for Adaptive Grid Based Hexmeshing",
// ACM TOG, Table "topology" (via /work/shared/DESIGN.md section 6). "-" = 0.
//                                     F3  F4  F5  F6  F7
constexpr PaperRow kRows[] = {
    {"F", {5, 10, 5, 0, 0}},
    {"F+C", {9, 9, 4, 2, 0}},
    {"C1", {4, 3, 3, 0, 0}},
    {"C2", {8, 1, 4, 1, 0}},
    {"C3", {12, 0, 3, 3, 0}},
    {"E", {8, 14, 7, 1, 0}},
    {"VC", {9, 21, 0, 6, 0}},
    {"VS", {8, 16, 3, 3, 0}},
    {"E-MR", {14, 10, 10, 2, 0}},
    {"VC1-MR", {16, 17, 4, 5, 1}},
    {"VC2-MR", {23, 14, 6, 5, 2}},
    {"VC3-MR", {30, 12, 6, 6, 3}},
    {"VS-MR", {15, 12, 7, 2, 1}},
};
}  // namespace

std::size_t PaperRow::count(int face_size) const {
    if (face_size < kPaperMinFaceSize || face_size > kPaperMaxFaceSize) return 0;
    return counts[static_cast<std::size_t>(face_size - kPaperMinFaceSize)];
}

std::span<const PaperRow> paper_table() { return kRows; }

std::optional<PaperRow> paper_row(std::string_view name) {
    for (const auto& r : kRows)
        if (r.name == name) return r;
    return std::nullopt;
}

bool PaperComparison::matches() const {
    for (const auto& c : columns)
        if (!c.equal()) return false;
    return outside_table.empty();
}

std::string PaperComparison::summary() const {
    std::ostringstream os;
    for (std::size_t i = 0; i < columns.size(); ++i) {
        const auto& c = columns[i];
        os << (i ? ", " : "") << 'F' << c.face_size << ' ' << c.computed << (c.equal() ? "=" : "!=") << c.paper;
    }
    for (const auto& [size, n] : outside_table) os << ", F" << size << ' ' << n << " (not in the table)";
    return os.str();
}

PaperComparison compare_with_paper(const std::map<int, std::size_t>& histogram, const PaperRow& row) {
    PaperComparison cmp;
    cmp.name = std::string(row.name);
    for (std::size_t i = 0; i < kPaperColumns; ++i) {
        const int size = kPaperMinFaceSize + static_cast<int>(i);
        auto it = histogram.find(size);
        cmp.columns[i] = {size, it == histogram.end() ? 0 : it->second, row.counts[i]};
    }
    for (const auto& [size, n] : histogram)
        if ((size < kPaperMinFaceSize || size > kPaperMaxFaceSize) && n > 0) cmp.outside_table[size] = n;
    return cmp;
}

}  // namespace dualhex
