#pragma once
// --bounces and the gather's knobs, one declaration for every command that lights the terrain
// (render, relight, tiles): light that bounces off the terrain (core/render/bounce_transfer.hpp).
#include <CLI/CLI.hpp>

#include "core/render/bounce_transfer.hpp"

namespace ts::app {

void add_bounce_options(CLI::App& cmd, render::BounceSettings& bounce);

}  // namespace ts::app
