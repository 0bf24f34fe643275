#pragma once
// Internal: a hash table shared by threads that finds, for every key occurring in several
// chunks, its occurrence in the smallest chunk (its "owner"). Insert-only, lock-free: a
// slot holds a reference ref + 1 (0 = empty), ref = chunk << 32 | local index; the keys live
// in the chunks' own (immutable) arrays, so `same(a, b)` compares the keys of two refs.
// Among equal keys a slot keeps the smallest ref (compare-and-swap minimum), so the owner
// does not depend on which thread inserted first; and it marks a key inserted more than
// once as shared (occurring in several chunks; each chunk inserts a key at most once).
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>

#include "dualhex/topology/id_hash_table.hpp"

namespace dualhex::detail {

class OwnerTable {
public:
    explicit OwnerTable(std::size_t n_keys) {
        std::size_t capacity = 16;
        while (capacity < 2 * n_keys) capacity *= 2;
        // Slots are returned as 32-bit numbers (as the chunks' vertex and face ids are).
        if (capacity > (std::size_t{1} << 32)) throw std::length_error("OwnerTable: more than 2^31 keys");
        slots_ = std::make_unique<std::atomic<std::uint64_t>[]>(capacity);
        for (std::size_t i = 0; i < capacity; ++i) slots_[i].store(0, std::memory_order_relaxed);
        mask_ = capacity - 1;
    }

    static std::uint64_t ref(std::size_t chunk, std::size_t local) { return std::uint64_t{chunk} << 32 | local; }
    static std::size_t chunk_of(std::uint64_t ref) { return static_cast<std::size_t>(ref >> 32); }
    static std::size_t local_of(std::uint64_t ref) { return static_cast<std::size_t>(ref & 0xFFFFFFFFU); }

    /// Records `r` for its key (hash `hash`), keeping the smallest ref of that key; returns
    /// the key's slot (fixed: the table never rehashes), for `at` once every insert is done.
    template <class Same>
    std::uint32_t insert(std::uint64_t hash, std::uint64_t r, Same&& same) {
        for (std::size_t i = mix64(hash) & mask_;; i = (i + 1) & mask_) {
            std::uint64_t cur = slots_[i].load(std::memory_order_acquire);
            while (cur == 0)
                if (slots_[i].compare_exchange_weak(cur, r + 1, std::memory_order_acq_rel)) return static_cast<std::uint32_t>(i);
            if (!same((cur & ~kShared) - 1, r)) continue;
            for (;;) {
                const std::uint64_t desired = std::min(cur & ~kShared, r + 1) | kShared;
                if (desired == cur || slots_[i].compare_exchange_weak(cur, desired, std::memory_order_acq_rel))
                    return static_cast<std::uint32_t>(i);
            }
        }
    }

    struct Owner {
        std::uint64_t ref = 0;  ///< the smallest ref of the key
        bool shared = false;    ///< inserted by more than one chunk
    };
    /// The owner of the key in `slot` (what insert returned); every insert must have
    /// finished. No hashing or key comparison: one load.
    [[nodiscard]] Owner at(std::uint32_t slot) const {
        const std::uint64_t cur = slots_[slot].load(std::memory_order_relaxed);
        return {(cur & ~kShared) - 1, (cur & kShared) != 0};
    }

private:
    static constexpr std::uint64_t kShared = std::uint64_t{1} << 63;
    std::unique_ptr<std::atomic<std::uint64_t>[]> slots_;
    std::size_t mask_ = 0;
};

}  // namespace dualhex::detail
