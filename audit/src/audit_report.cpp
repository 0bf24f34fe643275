// The audit's report as text and JSON, and the dispatch between the two modes.
#include <algorithm>
#include <sstream>

#include "audit_modes.hpp"
#include "dualhex/audit/audit.hpp"

namespace dualhex::audit {

bool AuditReport::ok() const {
    for (const CheckResult& c : checks)
        if (!c.passed()) return false;
    return true;
}

void add_violation(CheckResult& check, std::size_t max, Violation v) {
    ++check.violations;
    if (check.first.size() < max) check.first.push_back(std::move(v));
}

Violation at_points(const MeshFile& mesh, std::string what, std::vector<std::int64_t> points, std::int64_t file_cell) {
    Violation v;
    v.what = std::move(what);
    v.points = std::move(points);
    for (std::int64_t p : v.points) v.coordinates.push_back(mesh.points[static_cast<std::size_t>(p)]);
    if (file_cell >= 0) {
        v.cell = file_cell;
        // cells are in increasing file index (readers append in file order)
        const auto it = std::lower_bound(mesh.cells.begin(), mesh.cells.end(), file_cell,
                                         [](const MeshCell& c, std::int64_t i) { return static_cast<std::int64_t>(c.index) < i; });
        if (it != mesh.cells.end() && static_cast<std::int64_t>(it->index) == file_cell) v.line = it->line;
    }
    return v;
}

namespace {

std::string describe(const Violation& v) {
    std::ostringstream os;
    os.precision(17);
    os << v.what;
    if (v.cell >= 0) os << ": cell " << v.cell << " (line " << v.line << ")";
    if (!v.points.empty()) {
        os << (v.cell >= 0 ? "," : ":") << " points";
        for (std::size_t i = 0; i < v.points.size(); ++i) {
            const auto& c = v.coordinates[i];
            os << ' ' << v.points[i] << " (" << c[0] << ' ' << c[1] << ' ' << c[2] << ')';
        }
    }
    return os.str();
}

void print_statistic(std::ostream& os, const std::string& key, const nlohmann::json& value) {
    os << "  " << key << ": ";
    if (value.is_object()) {
        bool first = true;
        for (const auto& [k, v] : value.items()) {
            os << (first ? "" : ", ") << k << ": " << v.dump();
            first = false;
        }
        if (first) os << "-";
    } else {
        os << value.dump();
    }
    os << '\n';
}

}  // namespace

std::string AuditReport::text() const {
    std::ostringstream os;
    os << path << " (" << format << "): " << points << " points, " << cells << " volume cells";
    if (lower_dimensional_cells > 0) os << ", " << lower_dimensional_cells << " lower-dimensional cells (not audited)";
    os << "\nmode: " << mode << "\nstatistics:\n";
    for (const auto& [k, v] : statistics.items()) print_statistic(os, k, v);
    os << "checks:\n";
    for (const CheckResult& c : checks) {
        os << "  " << (c.passed() ? "PASS " : "FAIL ") << c.name << " (" << c.description << "; " << c.checked << ' '
           << c.checked_what << " checked)";
        if (!c.passed()) os << ": " << c.violations << " violation" << (c.violations == 1 ? "" : "s");
        os << '\n';
        for (const Violation& v : c.first) os << "    " << describe(v) << '\n';
        if (c.violations > c.first.size()) os << "    ... " << c.violations - c.first.size() << " more\n";
    }
    for (const std::string& n : notes) os << "note: " << n << '\n';
    os << (ok() ? "OK" : "FAILED") << '\n';
    return os.str();
}

nlohmann::json AuditReport::json() const {
    nlohmann::json checks_json = nlohmann::json::array();
    for (const CheckResult& c : checks) {
        nlohmann::json listed = nlohmann::json::array();
        for (const Violation& v : c.first) {
            nlohmann::json j{{"what", v.what}, {"points", v.points}, {"coordinates", v.coordinates}};
            if (v.cell >= 0) j["cell"] = v.cell, j["line"] = v.line;
            listed.push_back(j);
        }
        checks_json.push_back({{"name", c.name},
                               {"description", c.description},
                               {"passed", c.passed()},
                               {"violations", c.violations},
                               {"checked", c.checked},
                               {"checked_what", c.checked_what},
                               {"listed", listed}});
    }
    return {{"file", path},       {"format", format},         {"mode", mode},
            {"points", points},   {"cells", cells},           {"lower_dimensional_cells", lower_dimensional_cells},
            {"statistics", statistics}, {"checks", checks_json}, {"notes", notes},
            {"ok", ok()}};
}

AuditReport audit_mesh(const MeshFile& mesh, const AuditOptions& options) {
    AuditMode mode = options.mode;
    if (mode == AuditMode::Auto) {
        mode = AuditMode::Hex;
        for (const MeshCell& c : mesh.cells)
            if (c.type == kVtkPolyhedron) mode = AuditMode::Polyhedral;
    }
    AuditReport r;
    r.path = mesh.path;
    r.format = mesh.format;
    r.points = mesh.points.size();
    r.cells = mesh.cells.size();
    r.lower_dimensional_cells = mesh.lower_dimensional_cells;
    if (mode == AuditMode::Hex) detail::audit_hex(mesh, options, r);
    else detail::audit_polyhedral(mesh, options, r);
    return r;
}

}  // namespace dualhex::audit
