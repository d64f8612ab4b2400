#include "app/options/mesh_forward_option.hpp"

#include <filesystem>

#include "app/options/quantity_flags.hpp"
#include "core/util/error.hpp"

namespace ts::app {

void add_mesh_forward_option(CLI::App& cmd, std::string& forward) {
    cmd.add_option("--mesh-forward", forward,
                   "The mesh's nose axis after import (Z up), which the heading turns from north: auto (glTF: -y, "
                   "the spec's +Z front; AC3D and other formats: -x, FlightGear's nose), +x, -x, +y or -y "
                   "(docs/blockers.md)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "+x", "-x", "+y", "-y"}));
}

mesh::ForwardAxis mesh_forward_axis(const std::string& forward, const std::string& file) {
    if (forward == "auto") return mesh::default_forward_axis(std::filesystem::path(file).extension().string());
    try {
        return mesh::parse_forward_axis(forward);
    } catch (const QuantityError& e) {
        throw InputError(flag_message(e, "render"));
    }
}

std::string describe_mesh_forward(const std::string& forward, const std::string& file) {
    const std::string axis(mesh::forward_axis_name(mesh_forward_axis(forward, file)));
    if (forward != "auto") return "forward axis " + axis + " (--mesh-forward)";
    return "forward axis " + axis + (axis == "-y" ? " (auto: glTF's +Z front)" : " (auto: FlightGear's AC3D nose)") +
           ", turned north at heading 0";
}

}  // namespace ts::app
