// Csr: from_pairs and from_generator (Incidence's rows without a pair buffer) against a
// naive row-of-vectors reference, on random pair lists: same rows, items in emission order.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "dualhex/topology/csr.hpp"

using namespace dualhex;

namespace {

using Pairs = std::vector<std::pair<std::uint32_t, int>>;

std::vector<std::vector<int>> reference_rows(std::size_t n_rows, const Pairs& pairs) {
    std::vector<std::vector<int>> rows(n_rows);
    for (const auto& [row, item] : pairs) rows[row].push_back(item);
    return rows;
}

std::vector<std::vector<int>> rows_of(const Csr<int>& csr) {
    std::vector<std::vector<int>> rows;
    for (std::size_t r = 0; r < csr.size(); ++r) rows.emplace_back(csr[r].begin(), csr[r].end());
    return rows;
}

Pairs random_pairs(std::size_t n_rows) {
    const auto n = *rc::gen::inRange<std::size_t>(0, 200);
    Pairs pairs;
    for (std::size_t i = 0; i < n; ++i)
        pairs.emplace_back(*rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n_rows)), *rc::gen::arbitrary<int>());
    return pairs;
}

Csr<int> from_generator(std::size_t n_rows, const Pairs& pairs) {
    return Csr<int>::from_generator(n_rows, [&](auto&& emit) {
        for (const auto& [row, item] : pairs) emit(row, item);
    });
}

}  // namespace

RC_GTEST_PROP(TopologyCsr, FromGeneratorKeepsEveryRowInEmissionOrder, ()) {
    const auto n_rows = *rc::gen::inRange<std::size_t>(1, 30);
    const Pairs pairs = random_pairs(n_rows);
    const auto expected = reference_rows(n_rows, pairs);
    RC_ASSERT(rows_of(from_generator(n_rows, pairs)) == expected);
    RC_ASSERT(rows_of(Csr<int>::from_pairs(n_rows, pairs)) == expected);
}

TEST(TopologyCsr, RowsDifferWhenThePairsDo) {
    // The comparison above can fail: moving one item to another row, or swapping two items
    // of a row, changes the rows.
    const Pairs pairs = {{0, 1}, {2, 5}, {0, 2}, {1, 7}};
    const auto rows = rows_of(from_generator(3, pairs));
    EXPECT_EQ(rows, (std::vector<std::vector<int>>{{1, 2}, {7}, {5}}));
    EXPECT_NE(rows, rows_of(from_generator(3, {{0, 1}, {2, 5}, {1, 2}, {1, 7}})));
    EXPECT_NE(rows, rows_of(from_generator(3, {{0, 2}, {2, 5}, {0, 1}, {1, 7}})));
    EXPECT_EQ(rows_of(from_generator(4, {})), (std::vector<std::vector<int>>(4)));
}
