#pragma once
// For tests: a sky of uniform radiance over the upper hemisphere (none below) and a sun disc of
// a given irradiance in a given direction, whose shading has closed forms.
#include <string>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"

namespace ts::render::testing {

class UniformSky : public light::Sky {
public:
    UniformSky(float radiance, glm::dvec3 sun_dir, float sun_irradiance)
        : l_(radiance), sun_dir_(sun_dir), e_(sun_irradiance) {}
    // Radiance 1.
    UniformSky(glm::dvec3 sun_dir, float sun_irradiance) : UniformSky(1.0f, sun_dir, sun_irradiance) {}
    light::Rgb radiance(const glm::dvec3& d) const override { return light::Rgb(d.z > 0 ? l_ : 0.0f); }
    light::SunDisc sun() const override {
        light::SunDisc s;
        s.direction = sun_dir_;
        s.irradiance = light::Rgb(e_);
        return s;
    }
    std::string describe() const override { return "uniform test sky"; }

private:
    float l_;
    glm::dvec3 sun_dir_;
    float e_;
};

}  // namespace ts::render::testing
