// Parallel welding with the serial numbering (chunked_weld.hpp explains why it is the same).
//
// Memory: the merge runs one kind of array at a time (vertices, faces, cells): each step
// numbers what it needs, copies the chunks' owned entries into the merged array and frees
// the chunks' copies before the next step allocates, so the chunks' arrays and the merged
// ones are never all alive at once. A chunk's builder goes right after its emission (its
// welding tables are dead weight in the merge), and what marks a chunk's own vertex or face
// is its id (an owned one gets an id from the chunk's base up, a foreign one a smaller id:
// its owner is an earlier chunk), so the 8-byte owner refs go once the ids are known.
#include "chunked_weld.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "owner_table.hpp"

namespace dualhex::detail {
namespace {

// One chunk of consecutive leaves and what the merge learns about its vertices and faces.
struct Chunk {
    std::size_t begin = 0, end = 0;  // leaves
    ComplexBuilder::Parts parts;     // the builder's arrays; face loops turn global in place
    std::vector<std::uint32_t> leaf_cells;  // cells after each of its leaves (local count)
    // Per local vertex / face: its global id (owned: >= the chunk's base).
    std::vector<std::uint32_t> vertex_id, face_id;
    // Owner refs (OwnerTable), until the ids are known (first the keys' table slots).
    std::vector<std::uint64_t> vertex_owner, face_owner;
    std::vector<std::uint8_t> face_flip;  // foreign face met in the direction opposite to its owner's
    // Vertices some other chunk holds too; only a face all of whose vertices are shared can
    // be (its chunk alone owns the others: no table lookup).
    std::vector<std::uint8_t> vertex_shared;
    // The local faces' hashes over global vertex ids (invariant under rotation and reversal;
    // once inserted, a shared face's table slot), and whether all its vertices are shared (it may be in another chunk).
    std::vector<std::uint64_t> face_hash;
    std::vector<std::uint8_t> face_shared;
    std::size_t n_faces = 0, n_cells = 0, n_halffaces = 0;
    std::size_t owned_vertices = 0, owned_faces = 0, owned_loop_length = 0;
    std::size_t vertex_base = 0, face_base = 0, loop_base = 0, cell_base = 0, halfface_base = 0;

    [[nodiscard]] std::span<const VertexHandle> loop(std::size_t f) const {
        const auto& o = parts.face_offsets;
        return {parts.face_loops.data() + o[f], parts.face_loops.data() + o[f + 1]};
    }
    [[nodiscard]] bool owns_vertex(std::size_t i) const { return vertex_id[i] >= vertex_base; }
    [[nodiscard]] bool owns_face(std::size_t f) const { return face_id[f] >= face_base; }
};

using Chunks = std::vector<Chunk>;

template <class Body>
void for_each_chunk(Chunks& chunks, Body&& body) {
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) { body(chunks[c], c); });
}

template <class T>
void free_vector(std::vector<T>& v) {
    std::vector<T>().swap(v);
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
    ComplexBuilder builder;
    // Hash room for a quarter of the points: most are corners, welded densely by the caller.
    builder.reserve(m + m / 2, 4 * m, m + m / 2, m / 4);
    chunk.leaf_cells.reserve(m);
    emit(builder, chunk.begin, chunk.end, [&] { chunk.leaf_cells.push_back(static_cast<std::uint32_t>(builder.n_cells())); });
    chunk.n_faces = builder.n_faces();
    chunk.n_cells = builder.n_cells();
    chunk.parts = std::move(builder).take_parts();
    chunk.n_halffaces = chunk.parts.cell_halffaces.size();
}

// Ids of owned entries (owner(i) == c): consecutive from `base`, in local order.
template <class Owner>
void number_owned(std::vector<std::uint32_t>& id, std::size_t n, std::size_t base, Owner&& owned) {
    id.resize(n);
    auto next = static_cast<std::uint32_t>(base);
    for (std::size_t i = 0; i < n; ++i)
        if (owned(i)) id[i] = next++;
}

// Vertices: owners by lattice point, then ids (owned: consecutive per chunk in chunk order).
void number_vertices(Chunks& chunks) {
    std::size_t total = 0;
    for (const Chunk& c : chunks) total += c.parts.positions.size();
    OwnerTable table(total);
    const auto point = [&](std::uint64_t r) -> const LatticePoint& {
        return chunks[OwnerTable::chunk_of(r)].parts.positions[OwnerTable::local_of(r)];
    };
    const auto same = [&](std::uint64_t a, std::uint64_t b) { return point(a) == point(b); };
    // Each chunk remembers its keys' slots (in vertex_owner, until the refs replace them).
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        const auto& ps = chunk.parts.positions;
        chunk.vertex_owner.resize(ps.size());
        for (std::size_t i = 0; i < ps.size(); ++i)
            chunk.vertex_owner[i] = table.insert(LatticePointHash{}(ps[i]), OwnerTable::ref(c, i), same);
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        chunk.vertex_shared.resize(chunk.vertex_owner.size());
        for (std::size_t i = 0; i < chunk.vertex_owner.size(); ++i) {
            const OwnerTable::Owner o = table.at(static_cast<std::uint32_t>(chunk.vertex_owner[i]));
            chunk.vertex_owner[i] = o.ref;
            chunk.vertex_shared[i] = o.shared ? 1 : 0;
            chunk.owned_vertices += OwnerTable::chunk_of(o.ref) == c ? 1 : 0;
        }
    });
    for (std::size_t c = 0, base = 0; c < chunks.size(); base += chunks[c++].owned_vertices) chunks[c].vertex_base = base;
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        number_owned(chunk.vertex_id, chunk.vertex_owner.size(), chunk.vertex_base,
                     [&](std::size_t i) { return OwnerTable::chunk_of(chunk.vertex_owner[i]) == c; });
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        for (std::size_t i = 0; i < chunk.vertex_owner.size(); ++i) {
            const std::uint64_t r = chunk.vertex_owner[i];
            if (OwnerTable::chunk_of(r) != c) chunk.vertex_id[i] = chunks[OwnerTable::chunk_of(r)].vertex_id[OwnerTable::local_of(r)];
        }
    });
}

// The merged positions; the chunks' positions and owner refs are freed.
std::vector<LatticePoint> merge_positions(Chunks& chunks) {
    std::size_t n = 0;
    for (const Chunk& c : chunks) n += c.owned_vertices;
    std::vector<LatticePoint> positions(n);
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) {
        const auto& ps = chunk.parts.positions;
        for (std::size_t i = 0; i < ps.size(); ++i)
            if (chunk.owns_vertex(i)) positions[chunk.vertex_id[i]] = ps[i];
        free_vector(chunk.parts.positions);
        free_vector(chunk.vertex_owner);
    });
    return positions;
}

// The chunk's face loops turned, in place, into loops over global ids rotated to their
// smallest vertex, and hashed in the direction towards the smaller neighbour (as
// ComplexBuilder::add_face does). The vertex ids and shared marks are freed.
void global_loops(Chunk& chunk) {
    const auto& offsets = chunk.parts.face_offsets;
    const std::size_t nf = chunk.n_faces;
    chunk.face_hash.resize(nf);
    chunk.face_shared.assign(nf, 1);
    for (std::size_t f = 0; f < nf; ++f) {
        VertexHandle* loop = chunk.parts.face_loops.data() + offsets[f];
        const std::size_t n = offsets[f + 1] - offsets[f];
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t v = loop[k].index();
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
    free_vector(chunk.vertex_id);
    free_vector(chunk.vertex_shared);
}

// Faces: owners by loop, ids as for vertices, and the side flips of foreign faces.
void number_faces(Chunks& chunks) {
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) { global_loops(chunk); });
    std::size_t total = 0;
    for (const Chunk& c : chunks) total += static_cast<std::size_t>(std::count(c.face_shared.begin(), c.face_shared.end(), 1));
    OwnerTable table(total);
    const auto loop = [&](std::uint64_t r) { return chunks[OwnerTable::chunk_of(r)].loop(OwnerTable::local_of(r)); };
    const auto same = [&](std::uint64_t a, std::uint64_t b) { return same_cycle(loop(a), loop(b)); };
    // A shared face's slot goes where its hash was (no longer needed once inserted).
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        for (std::size_t f = 0; f < chunk.n_faces; ++f)
            if (chunk.face_shared[f]) chunk.face_hash[f] = table.insert(chunk.face_hash[f], OwnerTable::ref(c, f), same);
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        const std::size_t nf = chunk.n_faces;
        chunk.face_owner.resize(nf);
        chunk.face_flip.assign(nf, 0);
        for (std::size_t f = 0; f < nf; ++f) {
            const std::uint64_t r =
                chunk.face_shared[f] ? table.at(static_cast<std::uint32_t>(chunk.face_hash[f])).ref : OwnerTable::ref(c, f);
            chunk.face_owner[f] = r;
            if (OwnerTable::chunk_of(r) == c) {
                ++chunk.owned_faces;
                chunk.owned_loop_length += chunk.loop(f).size();
            } else {
                chunk.face_flip[f] = same_forward(chunk.loop(f), loop(r)) ? 0 : 1;
            }
        }
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) {
        free_vector(chunk.face_hash);
        free_vector(chunk.face_shared);
    });
    for (std::size_t c = 0, base = 0, loop_base = 0; c < chunks.size(); ++c) {
        chunks[c].face_base = base;
        chunks[c].loop_base = loop_base;
        base += chunks[c].owned_faces;
        loop_base += chunks[c].owned_loop_length;
    }
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        number_owned(chunk.face_id, chunk.n_faces, chunk.face_base,
                     [&](std::size_t f) { return OwnerTable::chunk_of(chunk.face_owner[f]) == c; });
    });
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t c) {
        for (std::size_t f = 0; f < chunk.n_faces; ++f) {
            const std::uint64_t r = chunk.face_owner[f];
            if (OwnerTable::chunk_of(r) != c) chunk.face_id[f] = chunks[OwnerTable::chunk_of(r)].face_id[OwnerTable::local_of(r)];
        }
    });
}

// The merged face loops (offsets and loops); the chunks' loops and owner refs are freed.
void merge_faces(Chunks& chunks, std::vector<std::uint32_t>& face_offsets, std::vector<VertexHandle>& face_loops) {
    std::size_t n_faces = 0, loop_length = 0;
    for (const Chunk& c : chunks) {
        n_faces += c.owned_faces;
        loop_length += c.owned_loop_length;
    }
    face_offsets.assign(n_faces + 1, 0);
    face_loops.resize(loop_length);
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) {
        std::size_t at = chunk.loop_base;
        for (std::size_t f = 0; f < chunk.n_faces; ++f) {
            if (!chunk.owns_face(f)) continue;
            for (VertexHandle v : chunk.loop(f)) face_loops[at++] = v;
            face_offsets[chunk.face_id[f] + 1] = static_cast<std::uint32_t>(at);
        }
        free_vector(chunk.parts.face_loops);
        free_vector(chunk.parts.face_offsets);
        free_vector(chunk.face_owner);
    });
}

// The merged cells (offsets and half-faces) and leaf_cells; the chunks are freed.
void merge_cells(Chunks& chunks, std::vector<std::uint32_t>& cell_offsets, std::vector<HalfFaceHandle>& halffaces,
                 std::vector<std::uint32_t>& leaf_cells, std::size_t n_leaves) {
    std::size_t n_cells = 0, n_halffaces = 0;
    for (Chunk& c : chunks) {
        c.cell_base = n_cells;
        c.halfface_base = n_halffaces;
        n_cells += c.n_cells;
        n_halffaces += c.n_halffaces;
    }
    cell_offsets.assign(n_cells + 1, 0);
    halffaces.resize(n_halffaces);
    leaf_cells.assign(n_leaves + 1, 0);
    for_each_chunk(chunks, [&](Chunk& chunk, std::size_t) {
        const auto& offsets = chunk.parts.cell_offsets;
        const auto& local = chunk.parts.cell_halffaces;
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
    std::vector<LatticePoint> positions = merge_positions(chunks);
    number_faces(chunks);
    std::vector<std::uint32_t> face_offsets, cell_offsets;
    std::vector<VertexHandle> face_loops;
    merge_faces(chunks, face_offsets, face_loops);
    std::vector<HalfFaceHandle> halffaces;
    merge_cells(chunks, cell_offsets, halffaces, leaf_cells, n_leaves);
    Chunks().swap(chunks);  // free the chunks' parts before the complex derives its edges
    return CellComplex(std::move(positions), std::move(face_offsets), std::move(face_loops), std::move(cell_offsets),
                       std::move(halffaces));
}

}  // namespace dualhex::detail
