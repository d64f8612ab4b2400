#include "app/options/sky_light_option.hpp"

#include "app/options/within_range.hpp"

namespace ts::app {

void add_sky_light_options(CLI::App& cmd, SkyLightArgs& a) {
    cmd.add_option("--sky-light", a.mode,
                   "The terrain's sky light: horizons (the sky integrated over each texel's horizons in "
                   "--sky-sectors sectors of azimuth) or sh (the sky's SH times each texel's transfer: cheaper per "
                   "frame, off by several % where the clear sky's bright horizon and aureole meet the terrain's "
                   "horizons; docs/rendering.md, \"The sky's light over the horizons\")")
        ->capture_default_str()
        ->check(CLI::IsMember({"horizons", "sh"}));
    cmd.add_option("--sky-sectors", a.sectors,
                   "--sky-light horizons: sectors of azimuth, at most this many (the largest divisor of --directions "
                   "up to it; more: finer, slower)")
        ->capture_default_str()
        ->check(within(1, 4096));
}

render::SkyLightSettings sky_light_settings(const SkyLightArgs& a) {
    render::SkyLightSettings s;
    s.mode = a.mode == "sh" ? render::SkyLightSettings::Mode::sh : render::SkyLightSettings::Mode::horizons;
    s.sectors = a.sectors;
    return s;
}

}  // namespace ts::app
