#include "app/options/bounce_option.hpp"

#include "app/options/within_range.hpp"

namespace ts::app {

void add_bounce_options(CLI::App& cmd, render::BounceSettings& b) {
    cmd.add_option("--bounces", b.bounces,
                   "Light bounced off the terrain: 0 (direct light only), 1 or 2 bounces (docs/rendering.md, "
                   "\"Bounced light\")")
        ->capture_default_str()
        ->check(CLI::IsMember({0, 1, 2}));
    cmd.add_option("--bounce-directions", b.gather.directions,
                   "Azimuths of the bounced light's gather (a divisor of --directions; more: finer, slower)")
        ->capture_default_str()
        ->check(within(1, 1024));
    cmd.add_option("--bounce-radius", b.gather.radius_texels,
                   "How far the bounced light's gather looks, texels (farther terrain is lit like open flat land)")
        ->capture_default_str()
        ->check(within(1, 1024));
}

}  // namespace ts::app
