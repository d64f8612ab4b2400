#include "app/options/quantity_flags.hpp"

namespace ts::app {

std::string_view flag_of(Quantity q, std::string_view command) {
    const bool hillshade = command == "hillshade";
    const bool spheres = command == "spheres" || command == "bench spheres";
    switch (q) {
        case Quantity::directions: return "--directions";
        case Quantity::sh_output: return "--sh";
        case Quantity::visibility_method: return "--method";
        case Quantity::pyramid_schedule: return "--pyramid-schedule";
        case Quantity::max_error: return "--max-error";
        case Quantity::exp_method: return "--exp-method";
        case Quantity::exposure: return "--exposure";
        case Quantity::extent: return "--extent";
        case Quantity::camera: return "--camera";
        case Quantity::image_size: return "--size";
        case Quantity::sky: return "--sky";
        case Quantity::sun_azimuth: return hillshade ? "--azimuth" : "--sun-azimuth";
        case Quantity::sun_elevation: return hillshade ? "--altitude" : "--sun-elevation";
        case Quantity::z_factor: return "--z-factor";
        case Quantity::exaggeration: return "--exaggeration";
        case Quantity::relief_contrast: return "--relief-contrast";
        case Quantity::tile_style: return "--style";
        case Quantity::resampling: return "--resampling";
        case Quantity::far_field: return "--far-field";
        case Quantity::zoom: return "--zoom";
        case Quantity::tile_size: return "--tile-size";
        case Quantity::block_texels: return "--block-texels";
        case Quantity::block_halo: return "--block-halo";
        case Quantity::level_bias: return "--level-bias";
        case Quantity::light_directions: return "--light-directions";
        case Quantity::light_components: return "--light-components";
        case Quantity::palette: return "--colors";
        case Quantity::resume: return "--resume";
        case Quantity::shard: return "--shard";
        case Quantity::crop: return "--crop";
        case Quantity::up_axis: return "--up";
        case Quantity::mesh_forward: return "--mesh-forward";
        case Quantity::sphere_count: return spheres ? "--count" : "--spheres";
        case Quantity::sphere_resolution: return "--resolution";
        case Quantity::memory_budget: return "--memory-budget";
        case Quantity::flight_path: return "--path";
        case Quantity::device: return "--device";
        case Quantity::ground_albedo: return "--albedo";
        case Quantity::clear_sky_index: return "--clear-sky-index";
        case Quantity::time_step: return "--step";
        case Quantity::period_split: return "--by";
        case Quantity::date_range: return "--to";
    }
    return "?";
}

std::string flag_message(const QuantityError& e, std::string_view command) {
    return e.named(flag_of(e.quantity(), command));
}

std::string flag_message(const OccupiedOutputError& e) {
    const OccupiedOutput& o = e.output();
    if (o.resuming)
        return o.path + ": " + o.holds + ": --resume continues only the same job; drop --resume and give --overwrite to " +
               "replace " + o.replaced + ", or choose another " + o.kind;
    return o.path + ": " + o.holds + "; give --overwrite to replace " + o.replaced + ", or --out another " + o.kind;
}

}  // namespace ts::app
