#include "app/options/night_option.hpp"

#include "core/util/error.hpp"

namespace ts::app {

void add_night_options(CLI::App& cmd, NightArgs& a) {
    cmd.add_option("--night", a.night,
                   "skip: leave out instants with the sun below -6 degrees (after civil dusk, before civil dawn; "
                   "said on the terminal); include: render them (sky light fading to black)")
        ->capture_default_str()
        ->check(CLI::IsMember({"skip", "include"}));
    // The earlier spelling, kept for scripts; not in --help.
    cmd.add_flag("--skip-night", a.skip_night)->group("");
}

bool skips_night(const NightArgs& a) {
    if (a.skip_night && a.night == "include") throw InputError("--skip-night and --night include contradict");
    return a.night == "skip" || a.skip_night;
}

}  // namespace ts::app
