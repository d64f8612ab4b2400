#include "app/options/sky_option.hpp"

namespace ts::app {

void add_sky_option(CLI::App& cmd, std::string& sky) {
    cmd.add_option("--sky", sky,
                   "Sky: clear[:turbidity=T,albedo=A,scattering=multiple|single,aureole=DEG] (sunlight scattered in a spherical "
                   "atmosphere: orange at sunset, twilight; also 'physical') | preetham[:turbidity=T,albedo=A] (Preetham 1999, "
                   "the default before) | overcast[:brightness=B] | PATH.exr|PATH.hdr (or "
                   "hdr:PATH[,rotation=DEG,scale=S]) "
                   "(docs/lighting.md)")
        ->capture_default_str();
}

}  // namespace ts::app
