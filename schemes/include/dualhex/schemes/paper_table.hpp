#pragma once
// The paper's per-element face-size counts, as cited data: Table "topology" of
//   M. Livesu, L. Pitzalis, G. Cherchi, "Optimal Dual Schemes for Adaptive Grid Based
//   Hexmeshing", ACM Transactions on Graphics (TOG).
// Numbers copied from /work/shared/DESIGN.md section 6 ("-" in the table is 0 here).
// All faces of the element count, including those on the leaf's boundary.
#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace dualhex {

/// Face sizes covered by the table: 3..7.
inline constexpr int kPaperMinFaceSize = 3;
inline constexpr int kPaperMaxFaceSize = 7;
inline constexpr std::size_t kPaperColumns = kPaperMaxFaceSize - kPaperMinFaceSize + 1;

struct PaperRow {
    std::string_view name;
    std::array<std::size_t, kPaperColumns> counts;  // F3, F4, F5, F6, F7

    [[nodiscard]] std::size_t count(int face_size) const;  // 0 outside 3..7
};

/// The 13 rows, in the paper's order (F, F+C, C1, C2, C3, E, VC, VS, E-MR, VC1-MR,
/// VC2-MR, VC3-MR, VS-MR).
[[nodiscard]] std::span<const PaperRow> paper_table();
[[nodiscard]] std::optional<PaperRow> paper_row(std::string_view name);

struct PaperColumn {
    int face_size = 0;
    std::size_t computed = 0, paper = 0;
    [[nodiscard]] bool equal() const { return computed == paper; }
};

struct PaperComparison {
    std::string name;
    std::array<PaperColumn, kPaperColumns> columns;  // F3..F7
    /// Computed face sizes outside 3..7 (the table has no column for them): never a match.
    std::map<int, std::size_t> outside_table;
    [[nodiscard]] bool matches() const;
    /// "F3 5=5, F4 10=10, F5 5=5, F6 0=0, F7 0=0" with "!=" where they differ.
    [[nodiscard]] std::string summary() const;
};

/// Compares a computed face-size histogram (size -> count, e.g. face_size_histogram) to
/// a row of the paper, column by column.
[[nodiscard]] PaperComparison compare_with_paper(const std::map<int, std::size_t>& histogram, const PaperRow& row);

}  // namespace dualhex
