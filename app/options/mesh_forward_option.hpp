#pragma once
// --mesh-forward, the axis of a mesh that is its nose, for every command that places meshes
// (render, relight, fly): one convention, core/mesh/forward_axis.hpp.
#include <string>

#include <CLI/CLI.hpp>

#include "core/mesh/forward_axis.hpp"

namespace ts::app {

// --mesh-forward auto|+x|-x|+y|-y (default auto).
void add_mesh_forward_option(CLI::App& cmd, std::string& forward);
// The axis for `file`: the given one, or by the file's format for auto. ts::InputError for a
// value that is none of these.
mesh::ForwardAxis mesh_forward_axis(const std::string& forward, const std::string& file);
// "forward axis -x (auto: AC3D and other formats)" for -v.
std::string describe_mesh_forward(const std::string& forward, const std::string& file);

}  // namespace ts::app
