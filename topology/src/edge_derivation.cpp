// Edge derivation by a stable parallel counting sort (edge_derivation.hpp).
#include "edge_derivation.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace dualhex::detail {
namespace {

// Marks a bucket slot whose edge already appeared earlier in the bucket; the low bits are
// then that edge's rank in the bucket (vertex ids are below 2^31).
constexpr std::uint32_t kRepeat = 0x80000000U;
constexpr std::size_t kVertexGrain = 4096;

struct Loops {
    const std::vector<std::uint32_t>& offsets;
    const std::vector<VertexHandle>& loops;

    // Calls side(corner, smaller, larger) for every corner of faces [f0, f1), in order.
    template <class Side>
    void sides(std::size_t f0, std::size_t f1, Side&& side) const {
        for (std::size_t f = f0; f < f1; ++f) {
            const std::uint32_t begin = offsets[f], end = offsets[f + 1];
            for (std::uint32_t c = begin; c < end; ++c) {
                const auto a = static_cast<std::uint32_t>(loops[c].idx);
                const auto b = static_cast<std::uint32_t>(loops[c + 1 == end ? begin : c + 1].idx);
                a < b ? side(c, a, b) : side(c, b, a);
            }
        }
    }
};

// Blocks of faces, one count row each: two per thread (so that a thread that starts late
// still gets a share), at most 8 (every block costs a row of n_vertices counts); one
// thread, one block (no extra pass).
std::size_t n_blocks(std::size_t n_faces) {
    const auto threads = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    return std::clamp<std::size_t>(std::min(threads == 1 ? 1 : 2 * threads, n_faces / 4096), 1, 8);
}

// 4-5 with one thread: per bucket in vertex order, a new larger endpoint is the next edge.
void number_serially(std::size_t nv, const std::vector<std::uint32_t>& bucket, const std::vector<std::uint32_t>& other,
                     const std::vector<std::uint32_t>& corner_of, DerivedEdges& out) {
    auto& edges = out.edge_vertices;
    for (std::size_t v = 0; v < nv; ++v) {
        const std::size_t first_edge = edges.size();
        for (std::uint32_t s = bucket[v]; s < bucket[v + 1]; ++s) {
            const VertexHandle w(static_cast<std::int32_t>(other[s]));
            std::size_t e = first_edge;
            while (e < edges.size() && edges[e][1] != w) ++e;
            if (e == edges.size()) edges.push_back({VertexHandle(v), w});
            out.face_edges[corner_of[s]] = EdgeHandle(e);
        }
    }
}

// 4-5 with more: the edges per vertex counted in parallel, numbered by a prefix sum, then
// written in parallel (the same numbering).
void number_in_parallel(std::size_t nv, const std::vector<std::uint32_t>& bucket, std::vector<std::uint32_t>& other,
                        const std::vector<std::uint32_t>& corner_of, DerivedEdges& out) {
    // 4. Per bucket, its distinct larger endpoints (edges); a repeat is marked with the
    // rank of its first occurrence. The edge count per vertex goes to first_edge.
    std::vector<std::uint32_t> first_edge(nv + 1, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kVertexGrain), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
            std::uint32_t rank = 0;
            for (std::uint32_t s = bucket[v]; s < bucket[v + 1]; ++s) {
                std::uint32_t seen = 0, j = bucket[v];
                for (; j < s; ++j) {
                    if (other[j] & kRepeat) continue;
                    if (other[j] == other[s]) break;
                    ++seen;
                }
                if (j < s) other[s] = kRepeat | seen;
                else ++rank;
            }
            first_edge[v + 1] = rank;
        }
    });
    for (std::size_t v = 0; v < nv; ++v) first_edge[v + 1] += first_edge[v];

    // 5. Number the edges: vertex v's are first_edge[v] + rank.
    out.edge_vertices.resize(first_edge[nv]);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kVertexGrain), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
            std::uint32_t next = first_edge[v];
            for (std::uint32_t s = bucket[v]; s < bucket[v + 1]; ++s) {
                std::uint32_t e;
                if (other[s] & kRepeat) {
                    e = first_edge[v] + (other[s] & ~kRepeat);
                } else {
                    e = next++;
                    out.edge_vertices[e] = {VertexHandle(v), VertexHandle(static_cast<std::int32_t>(other[s]))};
                }
                out.face_edges[corner_of[s]] = EdgeHandle(static_cast<std::size_t>(e));
            }
        }
    });
}

}  // namespace

DerivedEdges derive_edges(std::size_t nv, const std::vector<std::uint32_t>& face_offsets,
                          const std::vector<VertexHandle>& face_loops) {
    const Loops loops{face_offsets, face_loops};
    const std::size_t nf = face_offsets.size() - 1, n_corners = face_loops.size();
    const std::size_t blocks = n_blocks(nf);
    const auto block_faces = [&](std::size_t b) { return nf * b / blocks; };

    // Runs f(b) for every block; one block runs inline (a small complex: the tasks would
    // cost more than the work).
    const auto for_blocks = [&](auto&& f) {
        if (blocks == 1) f(std::size_t{0});
        else tbb::parallel_for(std::size_t{0}, blocks, f);
    };
    // 1. Per block, the number of sides per smaller endpoint.
    std::vector<std::uint32_t> cursor(blocks * nv, 0);
    for_blocks([&](std::size_t b) {
        std::uint32_t* count = cursor.data() + b * nv;
        loops.sides(block_faces(b), block_faces(b + 1), [&](std::uint32_t, std::uint32_t a, std::uint32_t) { ++count[a]; });
    });
    // 2. Bucket of vertex v = slots [bucket[v], bucket[v+1]); block b writes its sides of v
    // from cursor[b][v] on, after the blocks before it (stable: corner order in a bucket).
    std::vector<std::uint32_t> bucket(nv + 1, 0);
    std::uint32_t running = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        bucket[v] = running;
        for (std::size_t b = 0; b < blocks; ++b) {
            std::uint32_t& c = cursor[b * nv + v];
            const std::uint32_t n = c;
            c = running;
            running += n;
        }
    }
    bucket[nv] = running;
    // 3. Scatter: per slot the larger endpoint and the corner.
    std::vector<std::uint32_t> other(n_corners), corner_of(n_corners);
    for_blocks([&](std::size_t b) {
        std::uint32_t* slot = cursor.data() + b * nv;
        loops.sides(block_faces(b), block_faces(b + 1), [&](std::uint32_t c, std::uint32_t a, std::uint32_t far) {
            const std::uint32_t s = slot[a]++;
            other[s] = far;
            corner_of[s] = c;
        });
    });
    std::vector<std::uint32_t>().swap(cursor);

    DerivedEdges out;
    out.face_edges.resize(n_corners);
    if (blocks == 1) number_serially(nv, bucket, other, corner_of, out);
    else number_in_parallel(nv, bucket, other, corner_of, out);
    return out;
}

}  // namespace dualhex::detail
