#pragma once
// The three ways to find the horizon, by the name users type after --method.
#include <optional>
#include <string>
#include <string_view>

namespace ts::visibility {

enum class HorizonMethod {
    exact,     // sweep per azimuth with the convex hull of the profile (Timonen & Westerholm 2010)
    pyramid,   // multi-resolution marching over a mean height pyramid (the slides' method)
    raymarch,  // brute force over the bilinear surface, <= 0.25 texel steps: the reference
};

inline std::string_view method_name(HorizonMethod m) {
    switch (m) {
        case HorizonMethod::exact:
            return "exact";
        case HorizonMethod::pyramid:
            return "pyramid";
        case HorizonMethod::raymarch:
            return "raymarch";
    }
    return "?";
}

inline std::optional<HorizonMethod> parse_method(std::string_view name) {
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::pyramid, HorizonMethod::raymarch})
        if (method_name(m) == name) return m;
    return std::nullopt;
}

// The pyramid method's sampling schedule: sample k sits at tau_k = 2^(k / samples_per_octave)
// texels from the receiver and reads the level whose texel matches the gap to the next sample.
struct PyramidSchedule {
    std::string name;
    int samples_per_octave;
};

inline const PyramidSchedule* find_pyramid_schedule(std::string_view name) {
    static const PyramidSchedule kSchedules[] = {{"fast", 2}, {"balanced", 4}, {"fine", 8}, {"finest", 16}};
    for (const auto& s : kSchedules)
        if (s.name == name) return &s;
    return nullptr;
}

}  // namespace ts::visibility
