#include "app/options/sky_option.hpp"

namespace ts::app {

void add_sky_option(CLI::App& cmd, std::string& sky) {
    cmd.add_option("--sky", sky,
                   "Sky: clear[:turbidity=T,albedo=A] (Preetham 1999) | physical[:turbidity=T,albedo=A,scattering=multiple|single,aureole=DEG] "
                   "(a spherical atmosphere: orange at sunset, twilight) | overcast[:brightness=B] | PATH.exr|PATH.hdr (or "
                   "hdr:PATH[,rotation=DEG,scale=S]) "
                   "(docs/lighting.md)")
        ->capture_default_str();
}

}  // namespace ts::app
