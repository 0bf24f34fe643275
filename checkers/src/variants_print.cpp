// The text form of a variants report (variants_report.hpp, print).
#include <iomanip>
#include <ostream>
#include <sstream>

#include "dualhex/checkers/variants_report.hpp"

namespace dualhex::variants {
namespace {

std::string histogram_columns(const std::map<int, std::size_t>& h, int from = 3, int to = 7) {
    std::string out;
    for (int k = from; k <= to; ++k) {
        if (k > from) out += '/';
        const auto it = h.find(k);
        out += std::to_string(it == h.end() ? 0 : it->second);
    }
    return out;
}

}  // namespace

void print(std::ostream& os, const VariantsReport& report) {
    for (const auto& r : report.regions) {
        os << to_string(r.region) << ": torus " << format_mask(r.mask) << " (every coarse leaf a "
           << region_element(r.region) << "), " << r.variants.size() << " assignments, " << r.valid << " valid, "
           << r.classes.size() << " classes\n";
        os << "  " << std::left << std::setw(12) << "assignment" << std::setw(7) << "valid" << std::setw(16)
           << "faces F3..F7" << std::setw(28) << "bend faces" << std::setw(42) << "torus dual edge valences"
           << std::setw(10) << "singular"
           << "shipped\n";
        for (const auto& v : r.variants) {
            os << "  " << std::setw(12) << v.name << std::setw(7) << (v.ok() ? "yes" : "NO") << std::setw(16)
               << histogram_columns(v.element_faces) << std::setw(28)
               << (v.bend_faces.empty() ? std::string("-") : format_histogram(v.bend_faces)) << std::setw(42)
               << (v.torus.built ? format_histogram(v.torus.dual_edge_valences) : "ERROR " + v.torus.error)
               << std::setw(10) << singular_edges(v.torus.dual_edge_valences) << (v.shipped.empty() ? "-" : v.shipped)
               << '\n';
            if (!v.ok() && v.torus.built) os << "    " << v.torus.summary() << '\n';
        }
        os << "  classes by rank (max valence, then counts of valences > 4 from high to low; lower is better):\n";
        for (const auto& c : r.classes) {
            const auto& v = r.variants[c.members.front()];
            std::string members;
            for (std::size_t m : c.members) members += (members.empty() ? "" : ",") + r.variants[m].assignment;
            os << "    rank " << c.rank << "  {" << members << "}  bend face size " << v.bend_face_size
               << "  max valence " << c.ranking.front() << "  singular " << singular_edges(v.torus.dual_edge_valences)
               << "  torus " << format_histogram(v.torus.dual_edge_valences)
               << (v.shipped.empty() ? "" : "  = " + v.shipped) << (c.histograms_agree ? "" : "  MEMBERS DIFFER")
               << '\n';
        }
        os << '\n';
    }
    if (report.combined) {
        const auto& cr = *report.combined;
        os << "combined: every crossing touched by a bend free, per transition class (torus; limit 2^" << cr.limit
           << " assignments)\n";
        os << "  " << std::left << std::setw(12) << "class" << std::setw(6) << "fine" << std::setw(6) << "free"
           << std::setw(14) << "valid/total" << std::setw(36) << "strong rule" << std::setw(36) << "best"
           << "better/equal\n";
        for (const auto& c : cr.classes) {
            os << "  " << std::setw(12) << format_mask(c.representative) << std::setw(6) << c.fine << std::setw(6)
               << c.free_crossings << std::setw(14)
               << (c.enumerated ? std::to_string(c.valid) + "/" + std::to_string(c.assignments) +
                                      (c.componentwise ? " *" : "")
                                : "skipped")
               << std::setw(36) << format_histogram(c.strong_valences) << std::setw(36)
               << (c.enumerated ? format_histogram(c.best_valences) : "-")
               << (c.enumerated ? std::to_string(c.assignments_better) + "/" + std::to_string(c.assignments_equal)
                                : "-")
               << '\n';
        }
        os << "  * too many free crossings to enumerate jointly: each component (crossings linked by a leaf\n"
              "    with two or three interfaces) enumerated with the others at StrongRule's choice; the torus\n"
              "    histogram is a sum of per-leaf terms (a leaf's inner faces plus half its boundary faces), so\n"
              "    the best joint assignment is the best per component (lexicographic order is additive)\n";
        os << "  strong rule optimal in every enumerated class: " << (cr.strong_optimal() ? "yes" : "NO") << " ("
           << std::fixed << std::setprecision(1) << cr.seconds << " s)\n";
        os.unsetf(std::ios::fixed);
    }
}

}  // namespace dualhex::variants
