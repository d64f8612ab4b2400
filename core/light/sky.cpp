// make_sky: the --sky options to a radiance model.
#include "core/light/sky.hpp"

#include "core/light/hdr_sky.hpp"
#include "core/light/overcast_sky.hpp"
#include "core/light/physical_sky.hpp"
#include "core/light/preetham_sky.hpp"

namespace ts::light {

std::unique_ptr<Sky> make_sky(const SkyOptions& options, const glm::dvec3& sun_direction_enu) {
    switch (options.kind) {
        case SkyOptions::Kind::preetham:
            return std::make_unique<PreethamSky>(options.turbidity, options.ground_albedo, sun_direction_enu);
        case SkyOptions::Kind::physical:
        {
            auto sky = std::make_unique<PhysicalSky>(options.turbidity, options.ground_albedo, sun_direction_enu,
                                                     options.multiple_scattering ? Scattering::multiple : Scattering::single);
            sky->light_aureole_with_sun(options.aureole_deg);
            return sky;
        }
        case SkyOptions::Kind::overcast:
            return std::make_unique<OvercastSky>(options.overcast_brightness, options.ground_albedo, sun_direction_enu);
        case SkyOptions::Kind::hdr:
            return std::make_unique<HdrSky>(raster::read_float_image(options.hdr_path), options.hdr_path,
                                            options.hdr_rotation_deg, options.hdr_scale, sun_direction_enu);
    }
    return nullptr;
}

}  // namespace ts::light
