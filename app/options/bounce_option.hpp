#pragma once
// --bounces, --bounce-sun and the gather's knobs, one declaration for every command that lights the terrain
// (render, relight, tiles): light that bounces off the terrain (core/render/bounce_transfer.hpp).
#include <CLI/CLI.hpp>

#include "core/render/bounce_transfer.hpp"

namespace ts::app {

void add_bounce_options(CLI::App& cmd, render::BounceSettings& bounce);
// Throws ts::InputError naming the flags on settings the bounce refuses (before any heavy work).
void check_bounce_options(const render::BounceSettings& bounce);

}  // namespace ts::app
