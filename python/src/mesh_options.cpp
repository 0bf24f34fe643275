#include "mesh_options.hpp"

#include <functional>
#include <stdexcept>
#include <type_traits>

namespace dualhex::python {
namespace {

using Options = mesher::MeshPipelineOptions;

struct OptionBinding {
    std::string name;
    std::function<void(Options&, const py::handle&)> set;
    std::function<py::object(const Options&)> get;
};

// A plain field of Options or of a base of it (bool is not taken for a number).
template <class T, class Owner>
OptionBinding field(std::string name, T Owner::*member) {
    static_assert(std::is_base_of_v<Owner, Options>);
    return {name,
            [name, member](Options& o, const py::handle& v) {
                if constexpr (!std::is_same_v<T, bool>)
                    if (py::isinstance<py::bool_>(v)) throw py::type_error(name + ": expected a number, got bool");
                try {
                    o.*member = v.cast<T>();
                } catch (const py::cast_error&) {
                    throw py::type_error(name + ": cannot take a " + std::string(py::str(py::type::of(v))));
                }
            },
            [member](const Options& o) { return py::cast(o.*member); }};
}

OptionBinding balance_field() {
    return {"balance",
            [](Options& o, const py::handle& v) {
                const std::string s = py::isinstance<py::str>(v) ? v.cast<std::string>() : std::string(py::repr(v));
                if (s == "weak") o.balance = Balance::Weak;
                else if (s == "strong") o.balance = Balance::Strong;
                else throw std::invalid_argument("balance must be 'weak' or 'strong', got " + s);
            },
            [](const Options& o) { return py::cast(o.balance == Balance::Strong ? "strong" : "weak"); }};
}

// A field of a member struct of Options (e.g. optimise.min_quality), by the same rules.
template <class T, class Group>
OptionBinding nested_field(std::string name, Group Options::*group, T Group::*member) {
    return {name,
            [name, group, member](Options& o, const py::handle& v) {
                if (py::isinstance<py::bool_>(v)) throw py::type_error(name + ": expected a number, got bool");
                try {
                    (o.*group).*member = v.cast<T>();
                } catch (const py::cast_error&) {
                    throw py::type_error(name + ": cannot take a " + std::string(py::str(py::type::of(v))));
                }
            },
            [group, member](const Options& o) { return py::cast((o.*group).*member); }};
}

// One line per option of MeshPipelineOptions (mesher/mesh_pipeline.hpp).
const std::vector<OptionBinding>& options_table() {
    static const std::vector<OptionBinding> table{
        balance_field(),
        field("max_depth", &Options::max_depth),
        field("smooth_iterations", &Options::smooth_iterations),
        field("size", &Options::size),
        field("size_rel", &Options::size_rel),
        field("min_depth", &Options::min_depth),
        field("thickness_factor", &Options::thickness_factor),
        field("curvature_angle", &Options::curvature_angle),
        field("max_leaves", &Options::max_leaves),
        field("surface_band", &Options::surface_band),
        field("thickness_levels", &Options::thickness_levels),
        field("curvature_levels", &Options::curvature_levels),
        field("refine_rounds", &Options::refine_rounds),
        field("refine_distance", &Options::refine_distance),
        field("feature_angle", &Options::feature_angle),
        nested_field("min_quality", &Options::optimise, &mesher::OptimiseOptions::min_quality),
        nested_field("optimise_work", &Options::optimise, &mesher::OptimiseOptions::work_per_vertex),
        nested_field("optimise_ms", &Options::optimise, &mesher::OptimiseOptions::time_limit_ms),
        field("feature_min_chain", &Options::feature_min_chain),
        field("release_stuck", &Options::release_stuck),
        nested_field("core_margin", &Options::core, &mesher::CoreOptions::margin),
        nested_field("core_fill_margin", &Options::core, &mesher::CoreOptions::fill_margin),
        nested_field("pad_ray_limit", &Options::pad, &mesher::PadOptions::ray_limit),
    };
    return table;
}

// `preset` (coarse, medium, fine: the size options of `dualhex mesh --preset`) first, whatever
// the keyword order, so that the other options refine it as on the command line.
void apply_preset(const py::dict& kwargs, Options& options) {
    if (!kwargs.contains("preset")) return;
    const py::object v = kwargs["preset"];
    const std::string name = py::isinstance<py::str>(v) ? v.cast<std::string>() : std::string(py::repr(v));
    const auto preset = mesher::parse_mesh_preset(name);
    if (!preset) throw std::invalid_argument("preset must be 'coarse', 'medium' or 'fine', got " + name);
    static_cast<mesher::MeshSizeOptions&>(options) = mesher::mesh_preset(*preset);
}

}  // namespace

std::vector<std::string> mesh_option_names() {
    std::vector<std::string> names;
    for (const auto& o : options_table()) names.push_back(o.name);
    return names;
}

void apply_mesh_options(const py::dict& kwargs, Options& options) {
    apply_preset(kwargs, options);
    // An absolute size replaces the relative one, as `--size` does on the command line.
    if (kwargs.contains("size") && !kwargs.contains("size_rel")) options.size_rel = 0;
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::str(key);
        if (name == "preset") continue;
        const OptionBinding* binding = nullptr;
        for (const auto& o : options_table())
            if (o.name == name) binding = &o;
        if (!binding) {
            std::string known;
            for (const auto& n : mesh_option_names()) known += (known.empty() ? "" : ", ") + n;
            known += ", preset";
            throw py::type_error("mesh() got an unexpected keyword argument '" + name + "' (known: " + known + ")");
        }
        binding->set(options, value);
    }
}

py::dict mesh_options_dict(const Options& options) {
    py::dict d;
    for (const auto& o : options_table()) d[py::str(o.name)] = o.get(options);
    return d;
}

}  // namespace dualhex::python
