#pragma once
// Chain-crossing variants installed and ranked (issue 4; schemes/variants.hpp builds them).
//
// Every over/under assignment of a crossing region is installed in the periodic configuration
// of its region (flat: 0b11001100, concave edge: 0b00111111, concave corner: 0b01111111;
// every coarse leaf of those tori gets the region's element from StrongRule: F, E, VC) by a
// SubstitutingRule that places the variant wherever StrongRule places that element, with the
// same symmetry. The variants reach the torus through an ElementLibrary loaded (strictly:
// check_element must pass) from a temporary directory holding the shipped elements and the
// variants written in the element format.
//
// Classes: variants with equal canonical forms (schemes/variants.hpp: the 6 axis
// permutations, the symmetries fixing the application point and the leaf).
//
// Ranking (lower is better), on the installed torus's interior dual edge valences: first the
// maximum valence, then the counts of valences above 4 from the highest valence down (a
// lexicographic order on (max, n_max, ..., n_5)); valences 3 do not count.
//
// Combined (one step beyond the paper): for every one of the 20 transition classes, every
// crossing touched by a turning chain's bend (in a leaf with two or three interface faces) is
// left free; each assignment of those crossings is installed on the class representative's
// torus with a CrossingRule (the signature of StrongRule with the free crossings' lower chain
// taken from the assignment, matched against the shipped elements plus edge-UU and
// corner-XXY, the elements the shipped set lacks) and ranked as above.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/placement.hpp"
#include "dualhex/schemes/variants.hpp"
#include "dualhex/topology/progress.hpp"

namespace dualhex::variants {

/// Wherever `base` places element `from`, places `to` instead (same symmetry).
class SubstitutingRule : public TransitionRule {
public:
    SubstitutingRule(const TransitionRule& base, std::string from, std::string to)
        : base_(&base), from_(std::move(from)), to_(std::move(to)) {}
    [[nodiscard]] std::optional<Placement> place(const LeafContext& context) const override;
    [[nodiscard]] std::string name() const override { return base_->name() + "[" + from_ + "->" + to_ + "]"; }

private:
    const TransitionRule* base_;
    std::string from_, to_;
};

/// The torus mask of a region (torus convention, periodic_configuration.hpp).
[[nodiscard]] std::uint8_t region_mask(Region region);
/// The element StrongRule places in every coarse leaf of that torus: "F", "E", "VC".
[[nodiscard]] std::string region_element(Region region);

/// The shipped elements of `shipped` (a directory) plus `extra` (written as element files to
/// a fresh temporary directory, loaded with ElementLibrary::load, the directory removed).
/// Throws SchemeFormatError if an element is malformed or invalid (ElementLibrary::load is
/// strict) or a name collides.
[[nodiscard]] ElementLibrary library_with(const std::vector<ElementData>& extra,
                                          const std::filesystem::path& shipped = default_elements_directory());

/// The ranking key: {max valence, n_12, n_11, ..., n_5} (n_k = count of valence k).
[[nodiscard]] std::vector<std::size_t> ranking_key(const std::map<int, std::size_t>& dual_edge_valences);
/// Number of singular interior dual edges (valence != 4).
[[nodiscard]] std::size_t singular_edges(const std::map<int, std::size_t>& dual_edge_valences);

struct VariantResult {
    std::string name, assignment;
    bool element_valid = false;  ///< check_element on [0,12]^3
    std::vector<std::string> element_issues;
    ConfigurationReport torus;  ///< built = false with the error if the library refused it
    std::map<int, std::size_t> element_faces;  ///< all faces of the element
    std::map<int, std::size_t> bend_faces;     ///< distinct faces of the bend cells
    int bend_face_size = 0;                    ///< largest bend face (0 if no bend)
    std::string shipped;                       ///< shipped element with the same canonical form, or ""
    [[nodiscard]] bool ok() const { return element_valid && torus.ok(); }
};

/// Installs one variant in its region's torus (its own library) and checks it.
[[nodiscard]] VariantResult check_variant(const Variant& variant, const ElementLibrary* shipped_library = nullptr);

struct VariantClass {
    std::vector<std::size_t> members;  ///< indices into RegionReport::variants (first = representative)
    std::vector<std::size_t> ranking;  ///< ranking_key of the representative's torus
    int rank = 0;                      ///< 1 = best; equal keys share a rank
    bool histograms_agree = true;      ///< every member has the representative's histograms
};

struct RegionReport {
    Region region = Region::Flat;
    std::uint8_t mask = 0;
    std::vector<VariantResult> variants;  ///< in assignments(region) order
    std::vector<VariantClass> classes;    ///< sorted by rank
    std::size_t valid = 0;
};

[[nodiscard]] RegionReport check_region(Region region, const ElementLibrary& shipped);

struct CombinedClass {
    std::uint8_t representative = 0;  ///< smallest mask of the transition class
    int fine = 0;
    std::size_t free_crossings = 0;  ///< crossings touched by a bend
    std::size_t assignments = 0, valid = 0;
    bool enumerated = false;  ///< false: too many free crossings (> limit), strong rule only
    /// More than `limit` free crossings: each component (crossings linked by a leaf with two
    /// or three interfaces) enumerated on its own, the other crossings at StrongRule's choice.
    /// Exact for the ranking: the torus histogram is a sum of per-leaf terms (inner faces +
    /// half the boundary faces of each leaf's element), so a joint assignment's histogram is
    /// the strong one plus the per-component differences, and lexicographic order is additive.
    bool componentwise = false;
    std::vector<std::size_t> components;  ///< component sizes, largest first
    std::map<int, std::size_t> strong_valences;  ///< StrongRule's torus
    std::map<int, std::size_t> best_valences;    ///< best-ranked valid assignment's torus
    std::size_t assignments_better = 0;          ///< valid assignments ranked above StrongRule
    std::size_t assignments_equal = 0;           ///< valid assignments ranked equal to it
    [[nodiscard]] bool strong_optimal() const { return assignments_better == 0; }
};

struct CombinedReport {
    std::vector<CombinedClass> classes;  ///< the 20 transition classes
    std::size_t limit = 0;
    double seconds = 0;
    [[nodiscard]] bool strong_optimal() const;
};

/// Enumerates every assignment of the free crossings of each transition class (up to
/// 2^max_free_crossings per class). `progress` (optional): stage "assignments", those
/// installed and checked of all the classes'.
[[nodiscard]] CombinedReport check_combined(const ElementLibrary& shipped, std::size_t max_free_crossings = 12,
                                            const Progress& progress = {});

struct VariantsReport {
    std::vector<RegionReport> regions;  ///< flat, concave edge, concave corner
    std::optional<CombinedReport> combined;
    /// Every variant valid, classes 1/3/2, the best class of each region holds the shipped
    /// element (F, E, VC).
    [[nodiscard]] bool ok() const;
};

/// `progress` (optional): the combined enumeration's (check_combined).
[[nodiscard]] VariantsReport check_variants(bool combined = false, std::size_t max_free_crossings = 12,
                                            const Progress& progress = {});

/// The tables (per region: variants, classes by rank; then the combined table).
void print(std::ostream& os, const VariantsReport& report);

}  // namespace dualhex::variants
