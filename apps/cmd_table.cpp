// dualhex table: how the 8 strongly balanced elements realise the 20 transitions.
//
// For each configuration class (its representative mask at P = origin), each of the 8
// coarse-leaf positions around P gets the strong rule's placement. The rule also looks at
// the three octants across the leaf's coarse octant's far faces (the reach, see
// docs/scheme-derivation.md); here they are taken from the periodic embedding of the
// configuration (the 4x4x4-leaf 3-torus), as in the exhaustive check.
#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "dualhex/grid/configurations.hpp"
#include "dualhex/schemes/signature_rule.hpp"

namespace dualhex::app {
namespace {

/// World octant index (-1 or 0 per axis, wrapped with period 2) is fine in mask?
bool fine_world(std::uint8_t mask, int i, int j, int k) {
    auto wrap = [](int v) { return ((v % 2) + 2) % 2 == 1 ? -1 : 0; };  // ..,-2->0,-1->-1,0->0,1->-1
    const int b = (wrap(i) == 0 ? 1 : 0) | (wrap(j) == 0 ? 2 : 0) | (wrap(k) == 0 ? 4 : 0);
    return (mask >> b) & 1;
}

LeafContext periodic_context(std::uint8_t mask, int position) {
    LeafContext c;
    c.application_point = {0, 0, 0};
    c.direction = {position & 1 ? 1 : -1, position & 2 ? 1 : -1, position & 4 ? 1 : -1};
    for (int i = -2; i <= 1; ++i)
        for (int j = -2; j <= 1; ++j)
            for (int k = -2; k <= 1; ++k) {
                const int w[3] = {i, j, k};
                int world[3];
                for (int a = 0; a < 3; ++a) world[a] = c.direction[a] > 0 ? w[a] : -1 - w[a];
                c.set_fine(i, j, k, fine_world(mask, world[0], world[1], world[2]));
            }
    return c;
}

std::string position_name(int b) {
    std::string s;
    s += b & 1 ? "+x" : "-x";
    s += b & 2 ? "+y" : "-y";
    s += b & 4 ? "+z" : "-z";
    return s;
}

void run_table(bool json) {
    const ConfigurationSpace space(SymmetryGroup::Full);
    const StrongRule rule;
    nlohmann::json rows = nlohmann::json::array();
    std::map<std::string, int> used_by;  // element -> number of transition classes using it
    for (const auto& cls : space.classes()) {
        if (cls.fine == 0 || cls.fine == 8) continue;
        nlohmann::json leaves = nlohmann::json::array();
        std::map<std::string, bool> here;
        if (!json) std::cout << "class " << int(cls.representative) << " (" << cls.fine << " fine, " << cls.size << " configurations):";
        for (int b = 0; b < 8; ++b) {
            if ((cls.representative >> b) & 1) continue;  // a fine octant: no coarse leaf there
            const auto p = rule.place(periodic_context(cls.representative, b));
            const std::string name = p ? p->element : "hex";
            here[name] = true;
            leaves.push_back({{"position", position_name(b)},
                              {"element", name},
                              {"symmetry", p ? p->symmetry.to_string() : ""},
                              {"symmetry_index", p ? p->symmetry.index() : 0}});
            if (!json) std::cout << "  " << position_name(b) << ":" << name << (p ? " " + p->symmetry.to_string() : "");
        }
        if (!json) std::cout << '\n';
        for (const auto& [name, _] : here)
            if (name != "hex") ++used_by[name];
        rows.push_back({{"representative", cls.representative}, {"fine_octants", cls.fine}, {"size", cls.size}, {"leaves", leaves}});
    }
    if (json) {
        print_json({{"rule", rule.name()}, {"transitions", rows.size()}, {"classes", rows}, {"element_use", used_by}});
        return;
    }
    std::cout << rows.size() << " transitions from " << used_by.size() << " elements; transitions using each element:";
    for (const auto& [name, n] : used_by) std::cout << ' ' << name << '=' << n;
    std::cout << "\n(the rule also reads the octants across the leaf's octant's far faces; here they come from the\n"
                 " periodic embedding. VS, the 8th element, appears where a concave edge's octant ends at a concave\n"
                 " corner one octant away, which the periodic embedding of a single configuration cannot show;\n"
                 " `dualhex verify` exercises it in the cube windows.)\n";
}

}  // namespace

void register_table(CLI::App& app) {
    auto json = std::make_shared<bool>(false);
    auto* sub = app.add_subcommand("table", "Show which element (and symmetry) fills each coarse leaf of the 20 transitions");
    add_json_flag(*sub, *json);
    sub->callback([json] { run_table(*json); });
}

}  // namespace dualhex::app
