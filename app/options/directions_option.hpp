#pragma once
// --directions, the horizon azimuths of the sky visibility, for every command that shades with
// it (render, relight, tiles, fly, bench). `visibility` takes the same flag for its horizon
// products, where 1..4096 bands make sense, with a range of its own.
#include <CLI/CLI.hpp>

namespace ts::app {

inline constexpr int kMinDirections = 4;
inline constexpr int kMaxDirections = 1024;

// Adds --directions (4..1024; the default is `directions` as given); *given is set when the user
// typed it (--max-error chooses it otherwise). given may be nullptr.
CLI::Option* add_directions_option(CLI::App& cmd, int& directions, bool* given = nullptr);

}  // namespace ts::app
