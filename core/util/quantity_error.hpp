#pragma once
// An input error about one quantity a caller chose (a number of directions, an exposure, a
// zoom range...). core/ names the quantity, never the command-line flag that set it: the
// command line maps the quantity to the flag the user typed (app/options/quantity_flags.hpp),
// so a message reads "<the flag>: must be between 1 and 4096, got 5000" on the command line
// and "number of directions: must be ..." anywhere else.
#include <string>
#include <string_view>

#include "core/util/error.hpp"

namespace ts {

enum class Quantity {
    directions,        // horizon azimuths of a visibility sweep
    sh_output,         // the SH visibility product
    visibility_method, // exact, pyramid, ...
    pyramid_schedule,
    max_error,
    exp_method,
    exposure,
    extent,
    camera,
    image_size,
    sky,
    sun_azimuth,
    sun_elevation,
    z_factor,
    exaggeration,
    relief_contrast,
    tile_style,
    resampling,
    far_field,
    zoom,
    tile_size,
    block_texels,
    block_halo,
    level_bias,
    light_directions,  // a lightable tile's horizon azimuths
    light_components,  // a lightable tile's transfer components
    resume,            // continuing an interrupted job
    shard,
    crop,
    up_axis,
    mesh_forward,      // a mesh's nose axis
    sphere_count,
    sphere_resolution,
    memory_budget,
    flight_path,
    device,
    ground_albedo,     // insolation: the ground's albedo
    clear_sky_index,
    time_step,         // minutes between sun positions
    period_split,      // year, month or day
    date_range,        // the last day (before the first)
    palette,           // the land colours (a built-in palette or a colour table)
};

// The quantity in words ("number of directions").
std::string_view quantity_words(Quantity q);

class QuantityError : public InputError {
public:
    // `value` is what was given (may be empty), `problem` what is wrong with it; neither names
    // a flag.
    QuantityError(Quantity quantity, std::string value, std::string problem)
        : InputError(compose(quantity_words(quantity), value, problem)),
          quantity_(quantity),
          value_(std::move(value)),
          problem_(std::move(problem)) {}

    Quantity quantity() const { return quantity_; }
    // The same message with `name` (the flag the user typed) in place of the quantity's words.
    std::string named(std::string_view name) const { return compose(name, value_, problem_); }

private:
    static std::string compose(std::string_view name, const std::string& value, const std::string& problem) {
        std::string s(name);
        if (!value.empty()) s += " " + value;
        return s + ": " + problem;
    }
    Quantity quantity_;
    std::string value_, problem_;
};

}  // namespace ts

namespace ts {

// An output that already holds something else (another job's tiles, another frame series): the
// caller may replace it or write elsewhere; the command line names the flags that do
// (app/options/quantity_flags.hpp).
struct OccupiedOutput {
    std::string path;
    std::string holds;     // "holds tiles of another job (other options)"
    bool resuming = false;  // the caller asked to continue a job
    std::string replaced;  // what replacing removes: "it", "its tiles", "its frames and times.csv"
    std::string kind;      // "folder" or "file"
};

class OccupiedOutputError : public InputError {
public:
    explicit OccupiedOutputError(OccupiedOutput o)
        : InputError(o.path + ": " + o.holds +
                     (o.resuming ? ": resuming continues only the same job" : "") + "; replace " + o.replaced +
                     " or choose another " + o.kind),
          output_(std::move(o)) {}
    const OccupiedOutput& output() const { return output_; }

private:
    OccupiedOutput output_;
};

}  // namespace ts
