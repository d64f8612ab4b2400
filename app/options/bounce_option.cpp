#include "app/options/bounce_option.hpp"

#include <string>

#include "app/options/within_range.hpp"
#include "core/render/bounce_sun_gather.hpp"
#include "core/util/error.hpp"

namespace ts::app {

void add_bounce_options(CLI::App& cmd, render::BounceSettings& b) {
    cmd.add_option("--bounces", b.bounces,
                   "Light bounced off the terrain: 0 (direct light only), 1 or 2 bounces (docs/rendering.md, "
                   "\"Bounced light\")")
        ->capture_default_str()
        ->check(CLI::IsMember({0, 1, 2}));
    cmd.add_option("--bounce-directions", b.gather.directions,
                   "Azimuths of the bounced light's gather, at most this many (the largest divisor of --directions up "
                   "to it: its horizons are exact there; more: finer, slower)")
        ->capture_default_str()
        ->check(within(1, 1024));
    cmd.add_option_function<std::string>(
           "--bounce-sun",
           [&b](const std::string& v) {
               b.sun = v == "sh" ? render::BounceSettings::SunPart::sh : render::BounceSettings::SunPart::gather;
           },
           "The bounce's sun part: gather (per frame, from the light and shadow the terrain it sees really "
           "gets) or sh (through the bounce transfer's SH: smooth, blind to cast shadows; what the browser "
           "relights with)")
        ->default_str("gather")
        ->check(CLI::IsMember({"gather", "sh"}));
    cmd.add_option("--bounce-radius", b.gather.radius_texels,
                   "How far the bounced light's gather looks, texels (farther terrain is lit like open flat land; at "
                   "most " + std::to_string(render::kBounceSunGatherReach) + " with --bounce-sun gather)")
        ->capture_default_str()
        ->check(within(1, 1024));
    cmd.add_option("--bounce-growth", b.gather.growth,
                   "Ratio of each step of the bounced light's gather to the last (the first is one texel; more: "
                   "fewer, coarser steps far out)")
        ->capture_default_str()
        ->check(within(1.01, 4));
}

void check_bounce_options(const render::BounceSettings& b) {
    if (b.bounces > 0 && b.sun == render::BounceSettings::SunPart::gather &&
        b.gather.radius_texels > render::kBounceSunGatherReach)
        throw InputError("--bounce-radius above " + std::to_string(render::kBounceSunGatherReach) +
                         " texels needs --bounce-sun sh (the sun's gather keeps the terrain it sees within that)");
    render::check_bounce_settings(b);
}

}  // namespace ts::app
