#pragma once
// A physically based clear sky: sunlight scattered by air (Rayleigh) and by aerosol (Mie) in a
// spherical atmosphere with ozone absorption, integrated over wavelength. Single scattering as
// Nishita et al. ("Display of the Earth taking into account atmospheric scattering", SIGGRAPH
// 1993; the model behind Blender's "Nishita" sky), plus light scattered more than once
// (multiple_scattering.hpp). Unlike a fitted model it holds down to the horizon and at sunset: the long, low paths redden both the sun and the sky around it, and a sun below the
// horizon still lights the upper atmosphere (twilight) through the Earth's shadow.
//
// The sun's beam (`sun()`) is attenuated along the same atmosphere, so the disc and the sky
// redden together. Units as every Sky: linear Rec. 709 radiance with luminance in kcd/m^2;
// the extraterrestrial sun is light::kSolarIlluminanceKlx of 5778 K black-body light.
// Formulas, constants and their sources: docs/lighting.md, "Physical clear sky".
#include <array>
#include <memory>
#include <vector>

#include "core/light/atmosphere.hpp"
#include "core/light/multiple_scattering.hpp"
#include "core/light/sky.hpp"

namespace ts::light {

using atmosphere::Aerosol;

// How many times the light may scatter: once (Nishita's model, as Blender's "Nishita" sky), or
// any number of times (multiple_scattering.hpp), which lights the haze near the horizon and
// the twilight sky with the dome's own light.
enum class Scattering { single, multiple };

class PhysicalSky final : public Sky {
public:
    // Turbidity 1.7..10 (Angstrom beta as sun_transmittance.hpp, alpha 1.3), ground albedo 0..1.
    PhysicalSky(double turbidity, double ground_albedo, const glm::dvec3& sun_direction_enu,
                Scattering scattering = Scattering::multiple);
    // Any aerosol (tests match other models' with it); `turbidity` only names it in describe().
    PhysicalSky(const Aerosol& aerosol, double ground_albedo, const glm::dvec3& sun_direction_enu,
                Scattering scattering, double turbidity = 0.0);
    // Any atmosphere's coefficients (tests give every wavelength the same: a monochromatic sky).
    PhysicalSky(const atmosphere::Coefficients& coefficients, double ground_albedo, const glm::dvec3& sun_direction_enu,
                Scattering scattering);

    Rgb radiance(const glm::dvec3& dir) const override;
    // radiance() without the aureole that sun() carries (light_aureole_with_sun).
    Rgb lighting_radiance(const glm::dvec3& dir) const override;
    SunDisc sun() const override { return sun_; }

    // Lights the aerosol's circumsolar aureole with the sun's disc: the Mie radiance within
    // min(max_half_angle_deg, the sun's elevation) of the sun, above its value at that angle,
    // leaves lighting_radiance() and joins sun().irradiance (SunDisc::aureole says how much).
    // Why: order-4 SH spread a peak that holds 4-13% of the beam (the sun 8-50 degrees up) over 90 degrees, so
    // texels in the sun's cast shadow still saw much of it (docs/lighting.md, "The aureole
    // lit with the sun"). The cap stays above the horizon, so a surface that sees all of it gets
    // exactly its irradiance through the sun's cosine; one that sees part gets the sun's share.
    // 0 keeps the whole dome in lighting_radiance(). Call once, before use.
    void light_aureole_with_sun(double max_half_angle_deg);
    std::string describe() const override;

    // The dome alone for z > 0 (clamped to the horizon below).
    Rgb sky_radiance(const glm::dvec3& dir) const;
    // The same by integrating along the view ray now, without the table: the reference the
    // table is tested against (slow: one integral per call).
    Rgb sky_radiance_integrated(const glm::dvec3& dir) const;
    Rgb ground_radiance() const { return ground_; }
    Rgb sky_horizontal_irradiance() const { return sky_horizontal_; }

private:
    PhysicalSky(const atmosphere::Coefficients& coefficients, std::shared_ptr<const MultipleScattering> multiple,
                double ground_albedo, const glm::dvec3& sun_direction_enu, double turbidity);
    struct NodeRadiance {
        Rgb rayleigh{0.0f};  // radiance per unit Rayleigh phase function
        Rgb mie{0.0f};       // radiance per unit Mie phase function
        Rgb multiple{0.0f};  // radiance scattered more than once (isotropic)
    };
    NodeRadiance integrate(const glm::dvec3& view) const;
    // The table's integrals towards `dir` (z clamped to the horizon), interpolated.
    NodeRadiance node_at(const glm::dvec3& dir) const;
    // A direction's radiance from its two integrals and the phase functions at its angle to the
    // sun; the Mie phase capped at `mie_phase_cap`.
    Rgb with_phases(const NodeRadiance& n, const glm::dvec3& unit_view, double mie_phase_cap = 1e300) const;
    // The dome towards `dir` (clamped to the horizon) from the table, the Mie phase capped.
    Rgb dome(const glm::dvec3& dir, double mie_phase_cap) const;
    glm::dvec3 view_direction(double elevation_rad, double relative_azimuth_rad) const;

    double turbidity_;
    double albedo_;
    glm::dvec3 sun_dir_;
    glm::dvec3 sun_east_;  // horizontal unit vectors of the sun's frame (relative azimuth 0 = towards the sun)
    glm::dvec3 sun_north_;
    atmosphere::Coefficients coefficients_;
    std::shared_ptr<const MultipleScattering> multiple_;  // null for single scattering
    std::array<Rgb, atmosphere::kWavelengths> weight_{};  // extraterrestrial sun x colour matching -> linear RGB
    std::vector<NodeRadiance> table_;            // elevation-major
    SunDisc sun_;
    double aureole_phase_cap_ = 1e300;  // the Mie phase at the aureole's edge once it is lit with the sun
    Rgb sky_horizontal_{0.0f};
    Rgb ground_{0.0f};
};

}  // namespace ts::light
