#pragma once
// --night skip|include, one declaration for the commands that make or plan a frame series
// (relight, plan relight), so the plan counts the frames the job will render.
#include <string>

#include <CLI/CLI.hpp>

namespace ts::app {

// Below this sun elevation it is night: the end of civil twilight, when the sky is too dark for
// terrain to read without artificial light.
inline constexpr double kNightElevationDeg = -6.0;

struct NightArgs {
    std::string night = "skip";  // --night skip|include
    bool skip_night = false;     // --skip-night, the earlier spelling of --night skip (hidden)
};

void add_night_options(CLI::App& cmd, NightArgs& args);

// Whether night instants are left out; throws ts::InputError for --skip-night with --night include.
bool skips_night(const NightArgs& args);

}  // namespace ts::app
