#pragma once
// A flat open-addressing hash set of int32 ids (linear probing). The keys live elsewhere
// (in the caller's flat arrays), so the table stores only (hash, id) and asks the caller
// whether a stored id equals the probe. This is what lets the builder weld vertices and
// dedupe faces without a per-key heap allocation. A slot is 8 bytes: the id and the high
// 32 bits of the hash, which also pick the slot (so rehashing needs no callback).
#include <cstdint>
#include <utility>
#include <vector>

namespace dualhex::detail {

inline std::uint64_t mix64(std::uint64_t v) {
    v += 0x9e3779b97f4a7c15ULL;
    v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9ULL;
    v = (v ^ (v >> 27)) * 0x94d049bb133111ebULL;
    return v ^ (v >> 31);
}

class IdHashTable {
public:
    explicit IdHashTable(std::size_t expected = 16) { rehash(capacity_for(expected)); }

    void reserve(std::size_t expected) {
        if (capacity_for(expected) > slots_.size()) rehash(capacity_for(expected));
    }

    /// The stored id with this hash for which `equals(id)` holds, or -1.
    template <class Eq>
    [[nodiscard]] std::int32_t find(std::uint64_t hash, Eq&& equals) const {
        const auto tag = static_cast<std::uint32_t>(hash >> 32);
        for (std::size_t i = tag & mask_;; i = (i + 1) & mask_) {
            const Slot& s = slots_[i];
            if (s.id < 0) return -1;
            if (s.tag == tag && equals(s.id)) return s.id;
        }
    }

    /// Inserts `id` unless an equal id is stored; returns (stored id, inserted?).
    template <class Eq>
    std::pair<std::int32_t, bool> insert(std::uint64_t hash, std::int32_t id, Eq&& equals) {
        if (const std::int32_t found = find(hash, equals); found >= 0) return {found, false};
        if (2 * (size_ + 1) > slots_.size()) rehash(2 * slots_.size());
        place(static_cast<std::uint32_t>(hash >> 32), id);
        ++size_;
        return {id, true};
    }

private:
    struct Slot {
        std::uint32_t tag = 0;
        std::int32_t id = -1;
    };

    static std::size_t capacity_for(std::size_t n) {
        std::size_t c = 16;
        while (c < 2 * n) c *= 2;
        return c;
    }
    void place(std::uint32_t tag, std::int32_t id) {
        std::size_t i = tag & mask_;
        while (slots_[i].id >= 0) i = (i + 1) & mask_;
        slots_[i] = {tag, id};
    }
    void rehash(std::size_t capacity) {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(capacity, Slot{});
        mask_ = capacity - 1;
        for (const Slot& s : old)
            if (s.id >= 0) place(s.tag, s.id);
    }

    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::size_t size_ = 0;
};

// Like IdHashTable, but the caller picks where an id lives: its home slot is derived from a
// small integer `key` (key << shift), not from the hash, so ids whose keys are close sit
// close together. The builder keys faces by their smallest vertex id: a face and its
// later twin (the neighbouring cell's) are then looked up near the vertices being welded,
// instead of at a random slot of a large table (cache and TLB misses). The 32-bit tag
// (hash bits) filters before `equals` is asked. Rehashing asks `key_of(id)` for the key.
class LocalIdTable {
public:
    /// Room for keys below `keys` at 2^shift slots each (shift 2) without growing.
    explicit LocalIdTable(std::size_t keys = 4) {
        slots_.assign(capacity_for(keys), Slot{});
        mask_ = slots_.size() - 1;
    }

    template <class KeyOf>
    void reserve(std::size_t keys, KeyOf&& key_of) {
        if (capacity_for(keys) > slots_.size()) rehash(capacity_for(keys), shift_, key_of);
    }

    /// Inserts `id` (home from `key`) unless an equal id is stored; returns (stored id, inserted?).
    template <class Eq, class KeyOf>
    std::pair<std::int32_t, bool> insert(std::size_t key, std::uint32_t tag, std::int32_t id, Eq&& equals, KeyOf&& key_of) {
        if (((key + 1) << shift_) > slots_.size()) {
            std::size_t c = slots_.size();
            while (((key + 1) << shift_) > c) c *= 2;
            rehash(c, shift_, key_of);
        }
        std::size_t i = (key << shift_) & mask_;
        for (;; i = (i + 1) & mask_) {
            const Slot& s = slots_[i];
            if (s.id < 0) break;
            if (s.tag == tag && equals(s.id)) return {s.id, false};
        }
        if (8 * (size_ + 1) > 7 * slots_.size()) {
            rehash(2 * slots_.size(), shift_ + 1, key_of);
            place((key << shift_) & mask_, tag, id);
        } else {
            slots_[i] = {tag, id};
        }
        ++size_;
        return {id, true};
    }

private:
    struct Slot {
        std::uint32_t tag = 0;
        std::int32_t id = -1;
    };
    static constexpr int kShift = 2;

    std::size_t capacity_for(std::size_t keys) const {
        std::size_t c = 16;
        while (c < (keys << shift_)) c *= 2;
        return c;
    }
    void place(std::size_t i, std::uint32_t tag, std::int32_t id) {
        while (slots_[i].id >= 0) i = (i + 1) & mask_;
        slots_[i] = {tag, id};
    }
    template <class KeyOf>
    void rehash(std::size_t capacity, int shift, KeyOf&& key_of) {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(capacity, Slot{});
        mask_ = capacity - 1;
        shift_ = shift;
        for (const Slot& s : old)
            if (s.id >= 0) place((static_cast<std::size_t>(key_of(s.id)) << shift_) & mask_, s.tag, s.id);
    }

    int shift_ = kShift;
    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::size_t size_ = 0;
};

}  // namespace dualhex::detail
