#pragma once
// Compressed sparse rows: row i is items[offsets[i] .. offsets[i+1]). The one storage
// layout used for every variable-length relation in topology/ (face loops, cell
// half-faces, all incidence lists), so that a relation is two flat arrays.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace dualhex {

template <class T>
class Csr {
public:
    Csr() = default;

    [[nodiscard]] std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    [[nodiscard]] std::span<const T> operator[](std::size_t row) const {
        return {items_.data() + offsets_[row], items_.data() + offsets_[row + 1]};
    }

    /// Builds the rows from (row, item) pairs by a counting sort; within a row, items keep
    /// the order in which they appear in `pairs`. Every row must be < n_rows.
    static Csr from_pairs(std::size_t n_rows, const std::vector<std::pair<std::uint32_t, T>>& pairs) {
        Csr csr;
        csr.offsets_.assign(n_rows + 1, 0);
        for (const auto& [row, item] : pairs) ++csr.offsets_[row + 1];
        for (std::size_t r = 0; r < n_rows; ++r) csr.offsets_[r + 1] += csr.offsets_[r];
        csr.items_.resize(pairs.size());
        std::vector<std::uint32_t> cursor(csr.offsets_.begin(), csr.offsets_.end() - 1);
        for (const auto& [row, item] : pairs) csr.items_[cursor[row]++] = item;
        return csr;
    }

    /// The rows from_pairs builds from the (row, item) pairs that `generate(emit)` emits by
    /// calling emit(row, item), in the same order, without storing the pairs (their buffer
    /// was the peak of Incidence's memory): `generate` runs twice, once to count the items
    /// per row and once to place them, and must emit the same pairs both times.
    template <class Generate>
    static Csr from_generator(std::size_t n_rows, Generate&& generate) {
        Csr csr;
        csr.offsets_.assign(n_rows + 1, 0);
        generate([&](std::uint32_t row, const T&) { ++csr.offsets_[row + 1]; });
        for (std::size_t r = 0; r < n_rows; ++r) csr.offsets_[r + 1] += csr.offsets_[r];
        csr.items_.resize(csr.offsets_[n_rows]);
        std::vector<std::uint32_t> cursor(csr.offsets_.begin(), csr.offsets_.end() - 1);
        generate([&](std::uint32_t row, const T& item) { csr.items_[cursor[row]++] = item; });
        return csr;
    }

private:
    std::vector<std::uint32_t> offsets_{0};
    std::vector<T> items_;
};

}  // namespace dualhex
