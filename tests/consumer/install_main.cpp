// Uses the installed production layers: dualhex::install places the strong rule's elements
// into a two-level grid and verifies it; dualhex::mesher meshes the default torus.
#include <dualhex/grid/leaf_file.hpp>
#include <dualhex/install.hpp>
#include <dualhex/mesher/mesh_pipeline.hpp>
#include <dualhex/schemes/element_library.hpp>
#include <dualhex/schemes/signature_rule.hpp>

#include <iostream>
#include <string>

int main() {
    // The root split twice, then one level-2 cell split again with its 7 siblings (paired).
    std::string text;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
                if (i >= 2 || j >= 2 || k >= 2) text += "2 " + std::to_string(i) + ' ' + std::to_string(j) + ' ' +
                                                        std::to_string(k) + '\n';
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
                text += "3 " + std::to_string(i) + ' ' + std::to_string(j) + ' ' + std::to_string(k) + '\n';
    const dualhex::LeafGrid grid = dualhex::parse_leaves(text, "<consumer>");
    const auto library = dualhex::load_default_element_library();
    // The shipped elements come from the library itself, not from a directory on disk.
    const bool embedded = !library->elements().empty() &&
                          library->elements().front().file.parent_path() == dualhex::kEmbeddedElementsDirectory;
    std::cout << library->elements().size() << " elements" << (embedded ? ", embedded" : ", NOT embedded") << '\n';
    const dualhex::InstallResult installed = dualhex::install(grid, dualhex::StrongRule(), *library);
    const dualhex::InstallVerification check = dualhex::verify_installation(installed);
    std::cout << "installed " << installed.complex.n_cells() << " cells: " << check.summary() << '\n';

    dualhex::mesher::MeshPipelineOptions options;
    options.max_depth = 4;  // depth 3 is too coarse for a core inside the torus (EmptyCoreError)
    const dualhex::geometry::AabbTree tree(dualhex::mesher::default_shape());
    const dualhex::mesher::MeshPipelineResult mesh = dualhex::mesher::mesh_surface(tree, options);
    std::cout << "meshed the torus: " << mesh.mesh.hexes.size() << " hexes\n";
    const bool ok = embedded && library->elements().size() == 13 && check.ok() &&
                    installed.complex.n_cells() > grid.size() && !mesh.mesh.hexes.empty();
    std::cout << (ok ? "consumer (install, mesher) OK" : "consumer (install, mesher) FAILED") << '\n';
    return ok ? 0 : 1;
}
