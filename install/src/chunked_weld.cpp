// Parallel welding with the serial numbering (chunked_weld.hpp explains why it is the same).
#include "chunked_weld.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "owner_table.hpp"

namespace dualhex::detail {
namespace {

// One chunk of consecutive leaves and what the merge learns about its vertices and faces.
struct Chunk {
    std::size_t begin = 0, end = 0;  // leaves
    ComplexBuilder builder;
    std::vector<std::uint32_t> leaf_cells;  // cells after each of its leaves (local count)
    // Per local vertex / face: its global id and whether this chunk owns it.
    std::vector<std::uint32_t> vertex_id, face_id;
    std::vector<std::uint64_t> vertex_owner, face_owner;  // owner refs (OwnerTable)
    std::vector<std::uint8_t> face_flip;  // foreign face met in the direction opposite to its owner's
    // Vertices some other chunk holds too; only a face all of whose vertices are shared can
    // be (its chunk alone owns the others: no table lookup).
    std::vector<std::uint8_t> vertex_shared;
    // The local faces' loops over global vertex ids, rotated to their smallest id (offsets:
    // the builder's face_offsets), and their hashes (invariant under rotation and reversal).
    std::vector<VertexHandle> loops;
    std::vector<std::uint64_t> face_hash;
    std::vector<std::uint8_t> face_shared;  // all its vertices shared: it may be in another chunk
    std::size_t owned_vertices = 0, owned_faces = 0, owned_loop_length = 0;
    std::size_t vertex_base = 0, face_base = 0, loop_base = 0, cell_base = 0, halfface_base = 0;

    [[nodiscard]] std::span<const VertexHandle> loop(std::size_t f) const {
        const auto& o = builder.face_offsets();
        return {loops.data() + o[f], loops.data() + o[f + 1]};
    }
};

using Chunks = std::vector<Chunk>;

template <class Body>
void for_each_chunk(Chunks& chunks, Body&& body) {
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) { body(chunks[c], c); });
}

bool same_forward(std::span<const VertexHandle> a, std::span<const VertexHandle> b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}
// Both start at their smallest vertex: equal as cycles iff equal forward or backward.
bool same_cycle(std::span<const VertexHandle> a, std::span<const VertexHandle> b) {
    if (a.size() != b.size()) return false;
    if (same_forward(a, b)) return true;
    const std::size_t n = a.size();
    for (std::size_t k = 0; k < n; ++k)
        if (a[k] != b[k == 0 ? 0 : n - k]) return false;
    return true;
}

void emit_chunk(Chunk& chunk, const EmitRange& emit) {
    const std::size_t m = chunk.end - chunk.begin;
    // Hash room for a quarter of the points: most are corners, welded densely by the caller.
    chunk.builder.reserve(m + m / 2, 4 * m, m + m / 2, m / 4);
    chunk.leaf_cells.reserve(m);
    emit(chunk.builder, chunk.begin, chunk.end,
         [&] { chunk.leaf_cells.push_back(static_cast<std::uint32_t>(chunk.builder.n_cells())); });
}

// Vertices: owners by lattice point, then ids (owned: consecutive per chunk in chunk order).
void number_vertices(Chunks& chunks) {
    std::size_t total = 0;
    for (const Chunk& c : chunks) total += c.builder.n_vertices();
    OwnerTable table(total);
    const auto point = [&](std::uint64_t r) -> const LatticePoint& {
        return chunks[OwnerTable::chunk_of(r)].builder.positions()[OwnerTable::local_of(r)];
    };
    const auto same = [&](std::uint64_t a, std::uint64_t b) { return point(a) == point(b); };
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        const auto& ps = chunk.builder.positions();
        for (std::size_t i = 0; i < ps.size(); ++i) table.insert(LatticePointHash{}(ps[i]), OwnerTable::ref(c, i), same);
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        const auto& ps = chunk.builder.positions();
        chunk.vertex_owner.resize(ps.size());
        chunk.vertex_shared.resize(ps.size());
        for (std::size_t i = 0; i < ps.size(); ++i) {
            const OwnerTable::Owner o = table.owner(LatticePointHash{}(ps[i]), OwnerTable::ref(c, i), same);
            chunk.vertex_owner[i] = o.ref;
            chunk.vertex_shared[i] = o.shared ? 1 : 0;
            chunk.owned_vertices += OwnerTable::chunk_of(o.ref) == c ? 1 : 0;
        }
    });
    for (std::size_t c = 0, base = 0; c < chunks.size(); base += chunks[c++].owned_vertices) chunks[c].vertex_base = base;
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        chunk.vertex_id.resize(chunk.vertex_owner.size());
        std::uint32_t next = static_cast<std::uint32_t>(chunk.vertex_base);
        for (std::size_t i = 0; i < chunk.vertex_owner.size(); ++i)
            if (OwnerTable::chunk_of(chunk.vertex_owner[i]) == c) chunk.vertex_id[i] = next++;
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        for (std::size_t i = 0; i < chunk.vertex_owner.size(); ++i) {
            const std::uint64_t r = chunk.vertex_owner[i];
            if (OwnerTable::chunk_of(r) != c) chunk.vertex_id[i] = chunks[OwnerTable::chunk_of(r)].vertex_id[OwnerTable::local_of(r)];
        }
    });
}

// The chunk's face loops over global ids, rotated to their smallest vertex, and hashed in
// the direction towards the smaller neighbour (as ComplexBuilder::add_face does).
void global_loops(Chunk& chunk) {
    const auto& offsets = chunk.builder.face_offsets();
    const auto& local = chunk.builder.face_loops();
    chunk.loops.resize(local.size());
    const std::size_t nf = chunk.builder.n_faces();
    chunk.face_hash.resize(nf);
    chunk.face_shared.assign(nf, 1);
    for (std::size_t f = 0; f < nf; ++f) {
        VertexHandle* loop = chunk.loops.data() + offsets[f];
        const std::size_t n = offsets[f + 1] - offsets[f];
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t v = local[offsets[f] + k].index();
            loop[k] = VertexHandle(static_cast<std::int32_t>(chunk.vertex_id[v]));
            chunk.face_shared[f] &= chunk.vertex_shared[v];
        }
        std::rotate(loop, std::min_element(loop, loop + n), loop + n);
        if (!chunk.face_shared[f]) continue;
        const bool forward = n < 3 || loop[1] <= loop[n - 1];
        std::uint64_t hash = mix64(n);
        for (std::size_t k = 0; k < n; ++k) {
            const VertexHandle v = forward || k == 0 ? loop[k] : loop[n - k];
            hash = mix64(hash ^ static_cast<std::uint64_t>(v.idx));
        }
        chunk.face_hash[f] = hash;
    }
}

// Faces: owners by loop, ids as for vertices, and the side flips of foreign faces.
void number_faces(Chunks& chunks) {
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) { global_loops(chunk); });
    std::size_t total = 0;
    for (const Chunk& c : chunks) total += static_cast<std::size_t>(std::count(c.face_shared.begin(), c.face_shared.end(), 1));
    OwnerTable table(total);
    const auto loop = [&](std::uint64_t r) { return chunks[OwnerTable::chunk_of(r)].loop(OwnerTable::local_of(r)); };
    const auto same = [&](std::uint64_t a, std::uint64_t b) { return same_cycle(loop(a), loop(b)); };
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        for (std::size_t f = 0; f < chunk.face_hash.size(); ++f)
            if (chunk.face_shared[f]) table.insert(chunk.face_hash[f], OwnerTable::ref(c, f), same);
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        const std::size_t nf = chunk.face_hash.size();
        chunk.face_owner.resize(nf);
        chunk.face_flip.assign(nf, 0);
        for (std::size_t f = 0; f < nf; ++f) {
            const std::uint64_t r = chunk.face_shared[f] ? table.owner(chunk.face_hash[f], OwnerTable::ref(c, f), same).ref
                                                         : OwnerTable::ref(c, f);
            chunk.face_owner[f] = r;
            if (OwnerTable::chunk_of(r) == c) {
                ++chunk.owned_faces;
                chunk.owned_loop_length += chunk.loop(f).size();
            } else {
                chunk.face_flip[f] = same_forward(chunk.loop(f), loop(r)) ? 0 : 1;
            }
        }
    });
    for (std::size_t c = 0, base = 0, loop_base = 0; c < chunks.size(); ++c) {
        chunks[c].face_base = base;
        chunks[c].loop_base = loop_base;
        base += chunks[c].owned_faces;
        loop_base += chunks[c].owned_loop_length;
    }
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        chunk.face_id.resize(chunk.face_owner.size());
        std::uint32_t next = static_cast<std::uint32_t>(chunk.face_base);
        for (std::size_t f = 0; f < chunk.face_owner.size(); ++f)
            if (OwnerTable::chunk_of(chunk.face_owner[f]) == c) chunk.face_id[f] = next++;
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        for (std::size_t f = 0; f < chunk.face_owner.size(); ++f) {
            const std::uint64_t r = chunk.face_owner[f];
            if (OwnerTable::chunk_of(r) != c) chunk.face_id[f] = chunks[OwnerTable::chunk_of(r)].face_id[OwnerTable::local_of(r)];
        }
    });
}

}  // namespace

CellComplex weld_chunks(std::size_t n_leaves, std::size_t chunk_leaves, const EmitRange& emit,
                        std::vector<std::uint32_t>& leaf_cells) {
    Chunks chunks((n_leaves + chunk_leaves - 1) / std::max<std::size_t>(chunk_leaves, 1));
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        chunks[c].begin = c * chunk_leaves;
        chunks[c].end = std::min(n_leaves, (c + 1) * chunk_leaves);
    }
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) { emit_chunk(chunk, emit); });
    number_vertices(chunks);
    number_faces(chunks);

    std::size_t n_vertices = 0, n_faces = 0, loop_length = 0, n_cells = 0, n_halffaces = 0;
    for (Chunk& c : chunks) {
        c.cell_base = n_cells;
        c.halfface_base = n_halffaces;
        n_vertices += c.owned_vertices;
        n_faces += c.owned_faces;
        loop_length += c.owned_loop_length;
        n_cells += c.builder.n_cells();
        n_halffaces += c.builder.cell_halffaces().size();
    }
    std::vector<LatticePoint> positions(n_vertices);
    std::vector<std::uint32_t> face_offsets(n_faces + 1, 0), cell_offsets(n_cells + 1, 0);
    std::vector<VertexHandle> face_loops(loop_length);
    std::vector<HalfFaceHandle> halffaces(n_halffaces);
    leaf_cells.assign(n_leaves + 1, 0);
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        const auto& ps = chunk.builder.positions();
        for (std::size_t i = 0; i < ps.size(); ++i)
            if (OwnerTable::chunk_of(chunk.vertex_owner[i]) == c) positions[chunk.vertex_id[i]] = ps[i];
        std::size_t at = chunk.loop_base;
        for (std::size_t f = 0; f < chunk.face_owner.size(); ++f) {
            if (OwnerTable::chunk_of(chunk.face_owner[f]) != c) continue;
            for (VertexHandle v : chunk.loop(f)) face_loops[at++] = v;
            face_offsets[chunk.face_id[f] + 1] = static_cast<std::uint32_t>(at);
        }
        const auto& offsets = chunk.builder.cell_offsets();
        const auto& local = chunk.builder.cell_halffaces();
        for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
            cell_offsets[chunk.cell_base + k + 1] = static_cast<std::uint32_t>(chunk.halfface_base + offsets[k + 1]);
        for (std::size_t h = 0; h < local.size(); ++h) {
            const std::size_t f = local[h].face().index();
            halffaces[chunk.halfface_base + h] =
                HalfFaceHandle(FaceHandle(static_cast<std::int32_t>(chunk.face_id[f])), local[h].side() ^ chunk.face_flip[f]);
        }
        for (std::size_t j = 0; j < chunk.leaf_cells.size(); ++j)
            leaf_cells[chunk.begin + j + 1] = static_cast<std::uint32_t>(chunk.cell_base + chunk.leaf_cells[j]);
        chunk = Chunk();  // copied out, and no other chunk reads it any more: free it now (peak memory)
    });
    Chunks().swap(chunks);  // free the chunks' parts before the complex derives its edges
    return CellComplex(std::move(positions), std::move(face_offsets), std::move(face_loops), std::move(cell_offsets),
                       std::move(halffaces));
}

}  // namespace dualhex::detail
