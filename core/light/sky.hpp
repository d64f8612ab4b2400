#pragma once
// Sky lighting for shading: radiance of the sky dome (without the sun's disc) in the local ENU
// frame, and the sun treated apart as a disc (../shared/design/METHOD.md: its visibility comes
// from the exact horizon in its azimuth, so it must not be smeared into the order-4 SH).
//
// Units: linear RGB (Rec. 709 / sRGB primaries) radiance in kcd/m^2-like photometric units,
// the same for every model, so one exposure setting fits clear, overcast and HDR skies alike;
// the sun's irradiance is in the same units times steradians (radiance x solid angle).
#include <array>
#include <memory>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

namespace ts::light {

using Rgb = glm::vec3;

// What `--sky` asks for. Grammar (parse_sky_options):
//   clear[:turbidity=T,albedo=A,scattering=multiple|single,aureole=DEG]   (or physical[:...])
//                                  the clear sky scattered in a spherical atmosphere
//                                  (physical_sky.hpp; turbidity 1.7..10, ground albedo 0..1);
//                                  light scattered once only with scattering=single (as
//                                  Blender's Nishita sky);
//                                  the circumsolar aureole within `aureole` degrees (default
//                                  30, 0 = none) lights with the sun (PhysicalSky::
//                                  light_aureole_with_sun)
//   preetham[:turbidity=T,albedo=A]
//                                  Preetham et al.'s analytic clear sky (preetham_sky.hpp),
//                                  the default clear sky before the physical one
//   overcast[:brightness=B]        CIE standard overcast sky, zenith 3x the horizon
//   PATH.exr | PATH.hdr | hdr:PATH[,rotation=DEG,scale=S]
//                                  equirectangular HDR map (read through OpenImageIO)
struct SkyOptions {
    // The values are kept: tile sets describe their job with them (0 was and is Preetham's).
    enum class Kind { preetham = 0, physical = 1, overcast = 2, hdr = 3 };
    Kind kind = Kind::physical;
    double turbidity = 3.0;
    double ground_albedo = 0.2;
    double overcast_brightness = 1.0;  // scales the overcast zenith luminance
    bool multiple_scattering = true;   // physical: light scattered more than once as well
    double aureole_deg = 30.0;         // physical: PhysicalSky::light_aureole_with_sun's largest cap
    bool aureole_given = false;        // the spec named aureole= (else a renderer may pick its own)
    std::string hdr_path;
    double hdr_rotation_deg = 0.0;  // azimuth (clockwise from north) of the map's centre column
    double hdr_scale = 1.0;
};
// Throws ts::InputError with a one-line message for an unknown model or a bad parameter.
SkyOptions parse_sky_options(std::string_view text);

// The sun as a disc: where it is, how wide, and the irradiance it gives a surface facing it
// (after the atmosphere); irradiance 0 when it is below the horizon or the sky has no sun
// (overcast; an HDR map keeps its sun in its pixels).
struct SunDisc {
    glm::dvec3 direction{0.0, 0.0, 1.0};  // unit, ENU
    double angular_radius_rad = 0.004654;
    Rgb irradiance{0.0f};
    // Of `irradiance`, the sky's circumsolar aureole that a sky lights with the disc
    // (PhysicalSky::light_aureole_with_sun): it shades as the disc does; pictures of the sky
    // and mirrors draw the disc with irradiance - aureole, as the sky's radiance() has it.
    Rgb aureole{0.0f};
    Rgb disc_irradiance() const { return irradiance - aureole; }
};

class Sky {
public:
    virtual ~Sky() = default;
    // Radiance arriving from unit direction `dir` (ENU, pointing away from the receiver), the
    // sun's disc excluded. Below the horizon: light from the ground (albedo x irradiance / pi)
    // or 0, as the model says.
    virtual Rgb radiance(const glm::dvec3& dir) const = 0;
    // The radiance that shades: radiance() without what sun() carries of the sky (its
    // `aureole`). The SH projections and the exact references integrate this one.
    virtual Rgb lighting_radiance(const glm::dvec3& dir) const { return radiance(dir); }
    // The angular size (radians) of the finest detail of the lighting radiance that carries
    // light, for quadratures that sample it (a map's sun in its pixels); 0: smooth.
    virtual double lighting_detail_rad() const { return 0.0; }
    virtual SunDisc sun() const = 0;
    virtual std::string describe() const = 0;  // one line for logs and --help examples
};

// `sun_direction_enu` is the unit vector towards the sun (light::sun_direction_enu).
// Throws ts::InputError for an unreadable HDR map.
std::unique_ptr<Sky> make_sky(const SkyOptions& options, const glm::dvec3& sun_direction_enu);

// Order-4 real SH (sh_basis.hpp indexing, i = l*l + l + m) of the sky's radiance over the whole
// sphere, per RGB channel. Deterministic quadrature; see the implementation for its error.
using SkySh = std::array<Rgb, 16>;
SkySh project_sky_sh(const Sky& sky);
// The same with bands 0..2 fitted for diffuse terrain (sky_sh.hpp, diffuse_sky_fit.hpp): what the
// terrain's <T, L> takes.
SkySh project_diffuse_sky_sh(const Sky& sky);

}  // namespace ts::light
