#pragma once
// A flat open-addressing hash map from octree cells to small values. Octrees here reach
// 10^7 nodes, where std::unordered_map's per-node allocations dominate: this keeps keys
// packed (128 bits) in one array with linear probing. Insert-only (no erase): the
// algorithms that use it only ever refine, so a node changes value, it never vanishes.
#include <cstdint>
#include <utility>
#include <vector>

#include "dualhex/grid/leaf.hpp"

namespace dualhex {

/// A cell packed as two words: lo = i | j << 32, hi = k | (level + 1) << 32.
/// hi == 0 marks an empty slot (level + 1 >= 1 for every real cell).
struct CellKey {
    std::uint64_t lo = 0, hi = 0;
    bool operator==(const CellKey&) const = default;
};

[[nodiscard]] inline CellKey pack(const Leaf& c) {
    return {static_cast<std::uint64_t>(c.i) | static_cast<std::uint64_t>(c.j) << 32,
            static_cast<std::uint64_t>(c.k) | static_cast<std::uint64_t>(c.level + 1) << 32};
}

[[nodiscard]] inline Leaf unpack(const CellKey& key) {
    constexpr std::uint64_t low32 = 0xffffffffULL;
    return {static_cast<int>(key.hi >> 32) - 1, static_cast<std::int64_t>(key.lo & low32),
            static_cast<std::int64_t>(key.lo >> 32), static_cast<std::int64_t>(key.hi & low32)};
}

template <class V>
class CellMap {
public:
    explicit CellMap(std::size_t expected = 16) { rehash(capacity_for(expected)); }

    [[nodiscard]] std::size_t size() const { return size_; }

    /// Pointer to the value of `cell`, nullptr if absent. Valid until the next insert.
    [[nodiscard]] const V* find(const Leaf& cell) const { return find_key(pack(cell)); }
    [[nodiscard]] V* find(const Leaf& cell) { return const_cast<V*>(std::as_const(*this).find_key(pack(cell))); }
    [[nodiscard]] bool contains(const Leaf& cell) const { return find(cell) != nullptr; }

    /// Inserts (cell, value) if absent. Returns the stored value and whether it was inserted.
    std::pair<V*, bool> insert(const Leaf& cell, V value) {
        if (2 * (size_ + 1) > slots_.size()) rehash(2 * slots_.size());
        const CellKey key = pack(cell);
        std::size_t s = slot_of(key);
        while (slots_[s].key.hi != 0) {
            if (slots_[s].key == key) return {&slots_[s].value, false};
            s = (s + 1) & mask_;
        }
        slots_[s] = {key, value};
        ++size_;
        return {&slots_[s].value, true};
    }

    /// Calls f(cell, value) for every entry, in unspecified order.
    template <class F>
    void for_each(F&& f) const {
        for_each_in(0, slots_.size(), f);
    }
    /// The number of slots: for_each_in over disjoint slot ranges visits disjoint entries
    /// (read-only, so ranges can be visited in parallel).
    [[nodiscard]] std::size_t slot_count() const { return slots_.size(); }
    /// Calls f(cell, value) for the entries in slots [begin, end).
    template <class F>
    void for_each_in(std::size_t begin, std::size_t end, F&& f) const {
        for (std::size_t s = begin; s < end; ++s)
            if (slots_[s].key.hi != 0) f(unpack(slots_[s].key), slots_[s].value);
    }

private:
    struct Slot {
        CellKey key;
        V value{};
    };

    static std::size_t capacity_for(std::size_t n) {
        std::size_t c = 16;
        while (c < 2 * n) c *= 2;
        return c;
    }

    static std::uint64_t mix(std::uint64_t v) {  // splitmix64 finaliser
        v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9ULL;
        v = (v ^ (v >> 27)) * 0x94d049bb133111ebULL;
        return v ^ (v >> 31);
    }

    [[nodiscard]] std::size_t slot_of(const CellKey& key) const {
        return static_cast<std::size_t>(mix(key.lo ^ mix(key.hi + 0x9e3779b97f4a7c15ULL))) & mask_;
    }

    [[nodiscard]] const V* find_key(const CellKey& key) const {
        for (std::size_t s = slot_of(key);; s = (s + 1) & mask_) {
            if (slots_[s].key.hi == 0) return nullptr;
            if (slots_[s].key == key) return &slots_[s].value;
        }
    }

    void rehash(std::size_t capacity) {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(capacity, Slot{});
        mask_ = capacity - 1;
        size_ = 0;
        for (const auto& slot : old)
            if (slot.key.hi != 0) insert(unpack(slot.key), slot.value);
    }

    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::size_t size_ = 0;
};

}  // namespace dualhex
