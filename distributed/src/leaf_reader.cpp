// The distributed leaf-file reader (leaf_reader.hpp).
#include "leaf_reader.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdio>
#include <memory>
#include <optional>

#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "first_error.hpp"
#include "morton.hpp"

namespace dualhex::dist {
namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;
constexpr std::size_t kBlock = std::size_t{1} << 20;

// Every rank sees the same file system, so every rank reaches the same verdict here.
File open_regular(const std::string& name, std::uint64_t& size) {
    std::error_code ec;
    const auto status = std::filesystem::status(name, ec);
    if (ec || !std::filesystem::exists(status)) throw InputError(name, 0, "cannot open leaf file: no such file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(name, 0, "not a regular file");
    File file(std::fopen(name.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(name, 0, "cannot open leaf file");
    size = std::filesystem::file_size(name, ec);
    if (ec) throw InputError(name, 0, "cannot read leaf file");
    return file;
}

// The first line start at or after `offset`: a line belongs to the rank whose range holds
// its first byte.
std::uint64_t line_start_at_or_after(std::FILE* f, std::uint64_t offset, std::uint64_t size, std::uint64_t& read) {
    if (offset == 0 || offset >= size) return std::min(offset, size);
    fseeko(f, static_cast<off_t>(offset - 1), SEEK_SET);
    std::array<char, 128> buf{};  // lines are short: read little past the offset
    std::uint64_t pos = offset - 1;
    for (std::size_t got; (got = std::fread(buf.data(), 1, buf.size(), f)) > 0;) {
        read += got;
        for (std::size_t n = 0; n < got; ++n, ++pos)
            if (buf[n] == '\n') return pos + 1;
    }
    return size;
}

struct ParsedRange {
    std::vector<SortedLeaf> leaves;  // lines local (1 = the range's first line)
    std::int64_t lines = 0;
    std::optional<InputError> error;  // local line
};

void parse_line(std::string_view text, const std::string& source, ParsedRange& out) {
    ++out.lines;
    if (out.error) return;  // only count the lines after the first error
    const int local = out.lines > INT_MAX ? INT_MAX : static_cast<int>(out.lines);
    try {
        const std::optional<Leaf> leaf = parse_leaf_line(text, source, local);
        if (!leaf) return;
        if (leaf->level > kForestMaxLevel)
            throw InputError(source, local, "leaf " + to_string(*leaf) + ": level " + std::to_string(leaf->level) +
                                                " is beyond p8est's " + std::to_string(kForestMaxLevel));
        out.leaves.push_back({morton_position(*leaf), local, leaf->level});
    } catch (const InputError& e) {
        out.error = e;
    }
}

// Streams [begin, end) in blocks: memory is one block plus the leaves.
ParsedRange parse_range(std::FILE* f, std::uint64_t begin, std::uint64_t end, const std::string& source,
                        std::uint64_t& read) {
    ParsedRange out;
    fseeko(f, static_cast<off_t>(begin), SEEK_SET);
    std::string carry, block(kBlock, '\0');
    for (std::uint64_t pos = begin; pos < end;) {
        const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(kBlock, end - pos));
        const std::size_t got = std::fread(block.data(), 1, want, f);
        if (got == 0) throw InputError(source, 0, "cannot read leaf file");
        read += got;
        pos += got;
        std::string_view rest(block.data(), got);
        for (std::size_t eol; (eol = rest.find('\n')) != std::string_view::npos; rest.remove_prefix(eol + 1)) {
            if (carry.empty()) {
                parse_line(rest.substr(0, eol), source, out);
            } else {
                carry.append(rest.substr(0, eol));
                parse_line(carry, source, out);
                carry.clear();
            }
        }
        carry.append(rest);
    }
    if (!carry.empty()) parse_line(carry, source, out);  // a last line without '\n'
    return out;
}

bool before(const SortedLeaf& a, const SortedLeaf& b) {
    return a.position != b.position ? a.position < b.position : a.level != b.level ? a.level < b.level : a.line < b.line;
}

// The sample sort: np regular samples per rank, np - 1 splitters, one all-to-all; leaves at
// the same position go to the same rank.
std::vector<SortedLeaf> sort_over_ranks(MPI_Comm comm, std::vector<SortedLeaf> mine, std::uint64_t& bytes_out) {
    int size = 1;
    MPI_Comm_size(comm, &size);
    std::sort(mine.begin(), mine.end(), before);
    if (size == 1) return mine;
    const auto np = static_cast<std::size_t>(size);
    std::vector<std::uint64_t> samples(np, ~std::uint64_t{0}), all(np * np);
    for (std::size_t s = 0; s < np && !mine.empty(); ++s) samples[s] = mine[s * mine.size() / np].position;
    MPI_Allgather(samples.data(), size, MPI_UINT64_T, all.data(), size, MPI_UINT64_T, comm);
    std::sort(all.begin(), all.end());
    std::vector<std::uint64_t> splitters;
    for (std::size_t r = 1; r < np; ++r) splitters.push_back(all[r * np]);
    std::vector<int> send(np, 0), recv(np, 0), sdispl(np + 1, 0), rdispl(np + 1, 0);
    for (const SortedLeaf& l : mine)
        ++send[static_cast<std::size_t>(std::upper_bound(splitters.begin(), splitters.end(), l.position) - splitters.begin())];
    MPI_Alltoall(send.data(), 1, MPI_INT, recv.data(), 1, MPI_INT, comm);
    constexpr int kBytes = sizeof(SortedLeaf);
    for (std::size_t r = 0; r < np; ++r) {
        send[r] *= kBytes, recv[r] *= kBytes;
        sdispl[r + 1] = sdispl[r] + send[r], rdispl[r + 1] = rdispl[r] + recv[r];
    }
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    bytes_out = static_cast<std::uint64_t>(sdispl[np] - send[static_cast<std::size_t>(rank)]);  // to the other ranks
    std::vector<SortedLeaf> got(static_cast<std::size_t>(rdispl[np] / kBytes));
    MPI_Alltoallv(mine.data(), send.data(), sdispl.data(), MPI_BYTE, got.data(), recv.data(), rdispl.data(), MPI_BYTE,
                  comm);
    std::sort(got.begin(), got.end(), before);
    return got;
}

std::string describe(const SortedLeaf& l) {
    return to_string(morton_cell(l.position, l.level)) + " (line " + std::to_string(l.line) + ")";
}

// The largest cell starting at `from` and ending at or before `to` (from < to).
Leaf gap_cell(std::uint64_t from, std::uint64_t to) {
    int level = 0;
    while (from % morton_volume(level) != 0 || from + morton_volume(level) > to) ++level;
    return morton_cell(from, level);
}

std::optional<InputError> abut(const std::string& source, const SortedLeaf& a, const SortedLeaf& b) {
    const std::uint64_t end = a.position + morton_volume(a.level);
    if (b.position == end) return std::nullopt;
    if (b.position > end) {
        const Leaf c = gap_cell(end, b.position);
        return InputError(source, 0, "gap: cell " + to_string(c) + " (level " + std::to_string(c.level) +
                                         ") is not covered by any leaf");
    }
    if (b.position == a.position && b.level == a.level) {
        const SortedLeaf& first = a.line < b.line ? a : b;
        const SortedLeaf& second = a.line < b.line ? b : a;
        return InputError(source, second.line, "duplicate leaf " + describe(second) + ", first given as " + describe(first));
    }
    return InputError(source, b.line, "overlap: leaf " + describe(b) + " lies inside leaf " + describe(a));
}

// The tiling on the sorted runs: consecutive leaves abut, the first starts at 0, the last
// ends at the root's end. Each rank checks its run and the seam with the previous
// non-empty rank (every rank's first and last leaf, gathered).
std::optional<InputError> check_tiling(MPI_Comm comm, const std::string& source, const std::vector<SortedLeaf>& run) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    std::array<SortedLeaf, 2> ends{};
    ends[0].level = ends[1].level = -1;  // an empty run
    if (!run.empty()) ends = {run.front(), run.back()};
    std::vector<SortedLeaf> all(2 * static_cast<std::size_t>(size));
    MPI_Allgather(ends.data(), 2 * sizeof(SortedLeaf), MPI_BYTE, all.data(), 2 * sizeof(SortedLeaf), MPI_BYTE, comm);
    std::optional<SortedLeaf> previous, last;
    for (int r = 0; r < size; ++r) {
        const SortedLeaf& first = all[2 * static_cast<std::size_t>(r)];
        if (first.level < 0) continue;
        if (r < rank) previous = all[2 * static_cast<std::size_t>(r) + 1];
        last = all[2 * static_cast<std::size_t>(r) + 1];
    }
    if (!last) return InputError(source, 0, "gap: no leaves, the root cube 0 0 0 0 is not covered");
    if (run.empty()) return std::nullopt;
    if (!previous && run.front().position != 0) {
        const Leaf c = gap_cell(0, run.front().position);
        return InputError(source, 0, "gap: cell " + to_string(c) + " (level " + std::to_string(c.level) +
                                         ") is not covered by any leaf");
    }
    if (previous)
        if (auto e = abut(source, *previous, run.front())) return e;
    for (std::size_t n = 1; n < run.size(); ++n)
        if (auto e = abut(source, run[n - 1], run[n])) return e;
    const std::uint64_t root_end = morton_volume(0);
    if (run.back().position == last->position && run.back().line == last->line &&
        run.back().position + morton_volume(run.back().level) != root_end) {
        const std::uint64_t from = run.back().position + morton_volume(run.back().level);
        const Leaf c = gap_cell(from, root_end);
        return InputError(source, 0, "gap: cell " + to_string(c) + " (level " + std::to_string(c.level) +
                                         ") is not covered by any leaf");
    }
    return std::nullopt;
}

}  // namespace

DistributedLeaves read_leaves_distributed(MPI_Comm comm, const std::filesystem::path& path) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    DistributedLeaves out;
    out.source = path.string();
    std::uint64_t bytes = 0;
    const File file = open_regular(out.source, bytes);
    const auto np = static_cast<std::uint64_t>(size);
    const auto range = [&](int r) {  // r S / np without overflow
        const auto ur = static_cast<std::uint64_t>(r);
        return bytes / np * ur + bytes % np * ur / np;
    };
    const std::uint64_t begin = line_start_at_or_after(file.get(), range(rank), bytes, out.bytes_read);
    const std::uint64_t end = rank + 1 == size ? bytes : line_start_at_or_after(file.get(), range(rank + 1), bytes, out.bytes_read);
    ParsedRange parsed = begin < end ? parse_range(file.get(), begin, end, out.source, out.bytes_read) : ParsedRange{};
    out.lines_parsed = static_cast<std::uint64_t>(parsed.lines);
    out.leaves_parsed = parsed.leaves.size();
    std::int64_t before_me = 0;  // lines of the lower ranks
    MPI_Exscan(&parsed.lines, &before_me, 1, MPI_INT64_T, MPI_SUM, comm);
    if (rank == 0) before_me = 0;  // MPI_Exscan leaves rank 0's result undefined
    std::optional<InputError> error;
    if (parsed.error) error = InputError(out.source, static_cast<int>(std::min<std::int64_t>(INT_MAX, before_me + parsed.error->line())), parsed.error->message());
    else if (before_me + parsed.lines > INT_MAX) error = InputError(out.source, 0, "more than " + std::to_string(INT_MAX) + " lines");
    throw_first_error(comm, error);
    for (SortedLeaf& l : parsed.leaves) l.line += static_cast<std::int32_t>(before_me);
    out.leaves = sort_over_ranks(comm, std::move(parsed.leaves), out.bytes_sorted_out);
    throw_first_error(comm, check_tiling(comm, out.source, out.leaves));
    std::int64_t count = static_cast<std::int64_t>(out.leaves.size());
    int lo = INT_MAX, hi = 0;
    for (const SortedLeaf& l : out.leaves) lo = std::min(lo, l.level), hi = std::max(hi, l.level);
    MPI_Allreduce(&count, &out.global_count, 1, MPI_INT64_T, MPI_SUM, comm);
    MPI_Allreduce(&lo, &out.min_level, 1, MPI_INT, MPI_MIN, comm);
    MPI_Allreduce(&hi, &out.max_level, 1, MPI_INT, MPI_MAX, comm);
    return out;
}

}  // namespace dualhex::dist
