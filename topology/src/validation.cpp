#include "dualhex/topology/validation.hpp"

#include <tbb/parallel_for.h>

#include "checks.hpp"

namespace dualhex {
namespace {

// Appends part's findings to report (violations in order, counts added).
void append(ValidationReport& report, ValidationReport&& part) {
    for (Violation& v : part.violations) report.violations.push_back(std::move(v));
    for (std::size_t k = 0; k < kViolationKinds; ++k) report.per_kind[k] += part.per_kind[k];
    report.checked_faces += part.checked_faces;
    report.checked_cells += part.checked_cells;
    report.checked_vertices += part.checked_vertices;
    report.checked_edges += part.checked_edges;
}

// check(i, report) for every i in [0, n), in parallel over fixed blocks of ids: each block
// fills its own report and the blocks are appended in id order, so the report is the serial
// loop's, entry for entry, for any number of threads. The checks only read the complex.
template <class Check>
void check_each(std::size_t n, ValidationReport& report, Check&& check) {
    constexpr std::size_t kBlock = 4096;
    if (n <= kBlock) {
        for (std::size_t i = 0; i < n; ++i) check(i, report);
        return;
    }
    std::vector<ValidationReport> parts((n + kBlock - 1) / kBlock);
    tbb::parallel_for(std::size_t{0}, parts.size(), [&](std::size_t b) {
        for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) check(i, parts[b]);
    });
    for (ValidationReport& part : parts) append(report, std::move(part));
}

}  // namespace

ValidationReport validate(const CellComplex& k, const ValidationOptions& options) {
    ValidationReport report;
    check_each(k.n_faces(), report, [&](std::size_t f, ValidationReport& r) { detail::check_face(k, FaceHandle(f), r); });
    check_each(k.n_cells(), report, [&](std::size_t c, ValidationReport& r) { detail::check_cell(k, CellHandle(c), r); });
    report.checked_faces = k.n_faces();
    report.checked_cells = k.n_cells();

    const Incidence inc(k);
    check_each(k.n_faces(), report,
               [&](std::size_t f, ValidationReport& r) { detail::check_face_conformity(inc, FaceHandle(f), r); });
    detail::check_duplicate_cells(k, report);
    if (!options.check_interior) return report;

    auto accepted = [&](VertexHandle v) { return !options.interior_filter || options.interior_filter(v); };
    check_each(k.n_vertices(), report, [&](std::size_t i, ValidationReport& r) {
        const VertexHandle v(i);
        if (inc.is_boundary(v) || !accepted(v)) return;
        ++r.checked_vertices;
        detail::check_interior_vertex(k, inc, v, r);
    });
    check_each(k.n_edges(), report, [&](std::size_t i, ValidationReport& r) {
        const EdgeHandle e(i);
        const auto [a, b] = k.edge_vertices(e);
        if (inc.is_boundary(e) || !accepted(a) || !accepted(b)) return;
        ++r.checked_edges;
        detail::check_interior_edge(k, inc, e, r);
    });
    return report;
}

}  // namespace dualhex
