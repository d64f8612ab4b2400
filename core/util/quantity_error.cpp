#include "core/util/quantity_error.hpp"

namespace ts {

std::string_view quantity_words(Quantity q) {
    switch (q) {
        case Quantity::directions: return "number of directions";
        case Quantity::sh_output: return "SH visibility";
        case Quantity::visibility_method: return "visibility method";
        case Quantity::pyramid_schedule: return "pyramid schedule";
        case Quantity::max_error: return "error bound";
        case Quantity::exp_method: return "SH exponentiation method";
        case Quantity::exposure: return "exposure";
        case Quantity::extent: return "map extent";
        case Quantity::camera: return "camera";
        case Quantity::image_size: return "picture size";
        case Quantity::sky: return "sky";
        case Quantity::sun_azimuth: return "sun azimuth";
        case Quantity::sun_elevation: return "sun elevation";
        case Quantity::z_factor: return "vertical exaggeration";
        case Quantity::exaggeration: return "relief exaggeration";
        case Quantity::relief_contrast: return "relief contrast";
        case Quantity::tile_style: return "tile style";
        case Quantity::resampling: return "resampling";
        case Quantity::far_field: return "far field";
        case Quantity::zoom: return "zoom range";
        case Quantity::tile_size: return "tile size";
        case Quantity::block_texels: return "block size";
        case Quantity::block_halo: return "block halo";
        case Quantity::level_bias: return "level bias";
        case Quantity::light_directions: return "light directions";
        case Quantity::light_components: return "light components";
        case Quantity::palette: return "land colours";
        case Quantity::resume: return "resuming";
        case Quantity::shard: return "shard";
        case Quantity::crop: return "crop";
        case Quantity::up_axis: return "up axis";
        case Quantity::mesh_forward: return "mesh forward axis";
        case Quantity::sphere_count: return "number of spheres";
        case Quantity::sphere_resolution: return "voxel resolution";
        case Quantity::memory_budget: return "memory budget";
        case Quantity::flight_path: return "flight path";
        case Quantity::device: return "device";
        case Quantity::ground_albedo: return "ground albedo";
        case Quantity::clear_sky_index: return "clear-sky index";
        case Quantity::time_step: return "time step";
        case Quantity::period_split: return "period split";
        case Quantity::date_range: return "last day";
    }
    return "value";
}

}  // namespace ts
