#pragma once
// Internal: a configuration's complex as its builder left it, before the CellComplex is
// made. A class's members are only proved images of their representative, and their forms
// (oriented_form.hpp) read the vertices, face loops and cells, not the edges that
// CellComplex's constructor derives; so members are built as parts, and only a member
// that is not proved an image is completed and checked in full. (The constructor's other
// checks, offsets and handles in range, hold for any builder's output: add_face and
// add_cell refuse what would break them.)
#include <array>
#include <cstdint>
#include <functional>
#include <utility>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/install/element_templates.hpp"
#include "dualhex/topology/complex_builder.hpp"
#include "oriented_form.hpp"

namespace dualhex::detail {

struct ConfigurationParts {
    ConfigurationComplex header;  ///< everything but `complex` (left empty)
    ComplexBuilder::Parts parts;
};

/// The parts of a builder, with the header built so far.
inline ConfigurationParts parts_of(ConfigurationComplex header, ComplexBuilder&& builder) {
    return {std::move(header), std::move(builder).take_parts()};
}

/// The CellComplex of a builder's parts (edges derived): exactly what ComplexBuilder::build
/// would have made.
inline CellComplex complex_of(ComplexBuilder::Parts&& a) {
    return CellComplex(std::move(a.positions), std::move(a.face_offsets), std::move(a.face_loops),
                       std::move(a.cell_offsets), std::move(a.cell_halffaces));
}

/// The ConfigurationComplex, its CellComplex made from the parts.
inline ConfigurationComplex complete(ConfigurationParts&& p) {
    ConfigurationComplex out = std::move(p.header);
    out.complex = complex_of(std::move(p.parts));
    return out;
}

/// A built configuration's header and what its form reads, however it was built.
inline const ConfigurationComplex& header_of(const ConfigurationComplex& c) { return c; }
inline const ConfigurationComplex& header_of(const ConfigurationParts& p) { return p.header; }
inline const CellComplex& form_source(const ConfigurationComplex& c) { return c.complex; }
inline FormArrays form_source(const ConfigurationParts& p) { return FormArrays(p.parts); }

/// The parts behind build_periodic_configuration, build_cube_window, build_periodic_levels
/// and build_window_levels (configuration.cpp; each of those is complete() of these with a
/// cache of its own). A caller building many configurations passes one cache per thread:
/// the templates are the same whoever placed them first.
[[nodiscard]] ConfigurationParts periodic_configuration_parts(std::uint8_t mask, const TransitionRule& rule,
                                                              TemplateCache& cache);
[[nodiscard]] ConfigurationParts cube_window_parts(std::uint8_t mask, const TransitionRule& rule, TemplateCache& cache);
[[nodiscard]] ConfigurationParts periodic_levels_parts(const std::function<int(int, int, int)>& level, int n_octants,
                                                       const TransitionRule& rule, TemplateCache& cache);
[[nodiscard]] ConfigurationParts window_levels_parts(const std::array<int, 8>& levels, const TransitionRule& rule,
                                                     TemplateCache& cache);

}  // namespace dualhex::detail
