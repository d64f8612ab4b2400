#include "core/render/perspective_view.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "core/terrain/smooth_surface.hpp"
#include "core/terrain/valid_bilinear.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/earth_curvature.hpp"

namespace ts::render {
namespace {

// sin(3 deg): where the air light and the land beyond the DEM are read from the sky.
constexpr float kHorizonLift = 0.0523f;
// Neighbouring pixels whose terrain is this many times farther than the other's stand on
// either side of an edge of near terrain against far terrain (antialias_silhouettes).
constexpr float kDepthRatio = 1.25f;

double parse_number(std::string_view s, const std::string& what) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    double v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v))
        throw QuantityError(Quantity::camera, "", what + " '" + std::string(s) + "' is not a number");
    return v;
}

float surface(const terrain::HeightGrid& g, double x, double y) { return terrain::smooth_surface(g, x, y).z; }

}  // namespace

Camera parse_camera(std::string_view text) {
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (parts.size() != 6)
        throw QuantityError(Quantity::camera, std::string(text), "give lon,lat,height,heading,pitch,fov (6 numbers)");
    Camera c;
    c.lon_deg = parse_number(parts[0], "lon");
    c.lat_deg = parse_number(parts[1], "lat");
    c.height_m = parse_number(parts[2], "height");
    c.heading_deg = parse_number(parts[3], "heading");
    c.pitch_deg = parse_number(parts[4], "pitch");
    c.fov_deg = parse_number(parts[5], "fov");
    if (c.lat_deg < -90 || c.lat_deg > 90) throw QuantityError(Quantity::camera, "", "latitude must be in [-90, 90]");
    if (c.pitch_deg < -90 || c.pitch_deg > 90) throw QuantityError(Quantity::camera, "", "pitch must be in [-90, 90]");
    if (c.fov_deg <= 1 || c.fov_deg >= 170) throw QuantityError(Quantity::camera, "", "fov must be in (1, 170) degrees");
    return c;
}

std::string format_camera(const Camera& c) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.5f,%.5f,%.0f,%.1f,%.1f,%.0f", c.lon_deg, c.lat_deg, c.height_m, c.heading_deg,
                  c.pitch_deg, c.fov_deg);
    return buf;
}

Camera default_camera(const terrain::HeightGrid& g, const geo::Georef& georef) {
    const int mid = g.height / 2;
    const double dx = g.dx_m[std::size_t(mid)], dy = g.dy_m[std::size_t(mid)];
    const double extent = std::max((g.width - 1) * dx, (g.height - 1) * dy);
    double mean = 0, top = -1e30;
    std::size_t n = 0;
    for (float z : g.z)
        if (!std::isnan(z)) mean += z, ++n, top = std::max(top, double(z));
    mean = n ? mean / double(n) : 0.0;
    Camera c;
    c.heading_deg = 35.0;
    c.pitch_deg = -16.0;
    c.fov_deg = 55.0;
    const double back = 0.62 * extent;  // horizontal distance from the centre
    // Back along the heading as the grid sees it (a projected grid's north is not true north).
    const double grid_heading = radians(c.heading_deg + georef.grid_azimuth_of_north_deg());
    const double east = -back * std::sin(grid_heading), north = -back * std::cos(grid_heading);
    const double col = (g.width - 1) * 0.5 + east / dx, row = (g.height - 1) * 0.5 - north / dy;
    const glm::dvec2 ll = georef.pixel_to_lonlat(col + 0.5, row + 0.5);
    c.lon_deg = ll.x, c.lat_deg = ll.y;
    // Look down at the centre's mean height, at least 500 m above the highest point.
    c.height_m = std::max(mean + back * std::tan(radians(-c.pitch_deg)), top + 500.0);
    return c;
}

PerspectiveView::PerspectiveView(const terrain::HeightGrid& g, const geo::Georef& georef, const Camera& camera,
                                 const PerspectiveOptions& options)
    : grid_(g), options_(options) {
    if (options_.width < 1 || options_.height < 1 || options_.width > 16384 || options_.height > 16384)
        throw QuantityError(Quantity::image_size, "", "width and height must be in 1..16384");
    if (g.width < 2 || g.height < 2) throw InputError("perspective view: the DEM needs at least 2x2 texels");
    const glm::dvec2 px = georef.lonlat_to_pixel({camera.lon_deg, camera.lat_deg});
    cam_ = {px.x - 0.5, px.y - 0.5, camera.height_m};
    const int cam_row = std::clamp(int(std::lround(cam_.y)), 0, g.height - 1);
    const double dx = g.dx_m[std::size_t(cam_row)], dy = g.dy_m[std::size_t(cam_row)];
    const double curv = visibility::curvature_factor(options_.curvature);
    const float ground = surface(g, std::clamp(cam_.x, 0.0, double(g.width - 1)), std::clamp(cam_.y, 0.0, double(g.height - 1)));
    camera_inside_ = cam_.x >= 0 && cam_.y >= 0 && cam_.x <= g.width - 1 && cam_.y <= g.height - 1;
    below_terrain_ = camera_inside_ && !std::isnan(ground) && cam_.z <= double(ground);
    ground_m_ = double(ground);

    march_ = std::make_unique<SurfaceMarch>(g, options_.threads);
    // The heading is from true north; the grid's axes may lie elsewhere (a projected grid).
    const double h = radians(camera.heading_deg + georef.grid_azimuth_of_north_deg(px.x, px.y));
    const double p = radians(camera.pitch_deg);
    const glm::dvec3 forward{std::sin(h) * std::cos(p), std::cos(h) * std::cos(p), std::sin(p)};
    const glm::dvec3 right{std::cos(h), -std::sin(h), 0.0};
    const glm::dvec3 up{right.y * forward.z - right.z * forward.y, right.z * forward.x - right.x * forward.z,
                        right.x * forward.y - right.y * forward.x};
    const double half = std::tan(radians(0.5 * camera.fov_deg));
    const double aspect = double(options_.height) / options_.width;
    frame_ = {cam_, dx, dy, curv, forward, right, up, half, half * aspect};
    pixels_.assign(std::size_t(options_.width) * options_.height, Pixel{});

    parallel_rows(options_.height, options_.threads, options_.width * 400LL, [&](int j0, int j1) {
        for (int j = j0; j < j1; ++j)
            for (int i = 0; i < options_.width; ++i) pixels_[std::size_t(j) * options_.width + i] = trace(i + 0.5, j + 0.5);
    });
    antialias_silhouettes();
    // Only the per-frame sun rays need the pyramid again.
    if (!options_.pixel_sun_shadows) march_.reset();
}

PerspectiveView::Pixel PerspectiveView::trace(double u, double v) const {
    const terrain::HeightGrid& g = grid_;
    const Frame& f = frame_;
    const double dx = f.dx, dy = f.dy;
    const double half_w = f.half_width, half_h = f.half_height;
    // The shading normal at a hit: the smoothed slope (terrain::smooth_slope) of the surface the rays march.
    auto normal_at = [&](double x, double y) { return slope_normal(g, terrain::smooth_slope(g, x, y), y); };
    const double a = (2.0 * u / options_.width - 1.0) * half_w;
    const double b = (1.0 - 2.0 * v / options_.height) * half_h;
    glm::dvec3 d = f.forward + a * f.right + b * f.up;
    d /= std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    Pixel out;
    out.dir = glm::vec3(d);
    const double hl = std::hypot(d.x, d.y);
    if (below_terrain_) {
        out.x = float(cam_.x), out.y = float(cam_.y);
        out.normal = normal_at(cam_.x, cam_.y);
        return out;
    }
    if (hl < 1e-9) {  // straight down (or up)
        if (d.z < 0 && camera_inside_) {
            out.x = float(cam_.x), out.y = float(cam_.y), out.distance = float(cam_.z - ground_m_);
            out.normal = normal_at(cam_.x, cam_.y);
        }
        return out;
    }
    const SurfaceRay ray{cam_.x, cam_.y, d.x / hl / dx, -d.y / hl / dy, cam_.z, d.z / hl, f.curvature};
    // Clip to the grid's box of patches.
    double s0 = 0, s1 = std::numeric_limits<double>::infinity();
    auto clip = [&](double origin, double w, double lo, double hi) {
        if (std::abs(w) < 1e-15) {
            if (origin < lo || origin > hi) s1 = -1;
            return;
        }
        double ta = (lo - origin) / w, tb = (hi - origin) / w;
        if (ta > tb) std::swap(ta, tb);
        s0 = std::max(s0, ta), s1 = std::min(s1, tb);
    };
    clip(ray.x0, ray.ux, 0.0, g.width - 1.0);
    clip(ray.y0, ray.uy, 0.0, g.height - 1.0);
    if (!(s1 >= s0)) return out;
    const double s = march_->first_hit(ray, s0, s1, 1e-4 * std::min(dx, dy));
    if (s < 0) return out;
    out.x = float(ray.x0 + s * ray.ux), out.y = float(ray.y0 + s * ray.uy);
    out.normal = normal_at(out.x, out.y);
    const double distance = s / hl;
    out.distance = float(distance);
    out.transmittance = options_.haze_distance_m > 0 ? float(std::exp(-distance / options_.haze_distance_m)) : 1.0f;
    return out;
}

void PerspectiveView::antialias_silhouettes() {
    const int n = options_.edge_samples, w = options_.width, h = options_.height;
    if (n <= 1 || below_terrain_) return;
    auto at = [&](int i, int j) -> const Pixel& { return pixels_[std::size_t(j) * w + i]; };
    // Two neighbours on either side of an edge: one hits and one misses, or both hit at
    // distances kDepthRatio or more apart (near terrain in front of far terrain).
    auto apart = [&](const Pixel& a, const Pixel& b) {
        if ((a.x >= 0) != (b.x >= 0)) return true;
        if (a.x < 0) return false;
        const float lo = std::min(a.distance, b.distance), hi = std::max(a.distance, b.distance);
        return hi > kDepthRatio * lo;
    };
    std::vector<std::uint32_t> edge;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const Pixel& c = at(i, j);
            if ((i > 0 && apart(at(i - 1, j), c)) || (i + 1 < w && apart(at(i + 1, j), c)) ||
                (j > 0 && apart(at(i, j - 1), c)) || (j + 1 < h && apart(at(i, j + 1), c)))
                edge.push_back(std::uint32_t(j) * std::uint32_t(w) + std::uint32_t(i));
        }
    struct Done {
        Pixel front, behind;
        bool split = false;
    };
    std::vector<Done> done(edge.size());
    parallel_rows(int(edge.size()), options_.threads, 400LL * n * n, [&](int e0, int e1) {
        std::vector<Pixel> hits;
        std::vector<double> offset;
        for (int e = e0; e < e1; ++e) {
            const int i = int(edge[std::size_t(e)] % std::uint32_t(w)), j = int(edge[std::size_t(e)] / std::uint32_t(w));
            const Pixel centre = pixels_[edge[std::size_t(e)]];
            hits.clear(), offset.clear();
            float nearest_d = std::numeric_limits<float>::infinity(), farthest_d = 0;
            for (int b = 0; b < n; ++b)
                for (int a = 0; a < n; ++a) {
                    const double du = (a + 0.5) / n, dv = (b + 0.5) / n;
                    const Pixel q = trace(i + du, j + dv);
                    if (q.x < 0) continue;
                    hits.push_back(q);
                    offset.push_back((du - 0.5) * (du - 0.5) + (dv - 0.5) * (dv - 0.5));
                    nearest_d = std::min(nearest_d, q.distance), farthest_d = std::max(farthest_d, q.distance);
                }
            // The rays' hits in one group, or split into near and far at the geometric mean of
            // their distances; each group is shaded at its hit nearest the pixel's centre.
            const bool split = farthest_d > kDepthRatio * nearest_d;
            const float cut = std::sqrt(nearest_d * farthest_d);
            int front_hits = 0, behind_hits = 0;
            double front_off = std::numeric_limits<double>::infinity(), behind_off = front_off;
            Pixel front, behind;
            for (std::size_t k = 0; k < hits.size(); ++k) {
                if (!split || hits[k].distance < cut) {
                    ++front_hits;
                    if (offset[k] < front_off) front_off = offset[k], front = hits[k];
                } else {
                    ++behind_hits;
                    if (offset[k] < behind_off) behind_off = offset[k], behind = hits[k];
                }
            }
            Done& d = done[std::size_t(e)];
            d.front = centre;
            // A centre that missed, or that hit the far group, takes the front's hit nearest it;
            // the pixel's direction stays the centre's.
            if ((centre.x < 0 || (split && centre.distance >= cut)) && front_hits > 0) {
                const glm::vec3 dir = centre.dir;
                d.front = front;
                d.front.dir = dir;
            }
            d.front.coverage = float(front_hits) / float(n * n);
            d.split = split && behind_hits > 0;
            if (d.split) {
                d.behind = behind;
                d.behind.coverage = float(behind_hits) / float(n * n);
            }
        }
    });
    for (std::size_t e = 0; e < edge.size(); ++e) {
        Pixel& p = pixels_[edge[e]];
        p = done[e].front;
        p.behind = -1;
        if (done[e].split) {
            p.behind = std::int32_t(behind_.size());
            behind_.push_back(done[e].behind);
        }
    }
}

std::vector<glm::vec3> PerspectiveView::view_directions() const {
    const terrain::HeightGrid& g = grid_;
    const int cam_row = std::clamp(int(std::lround(cam_.y)), 0, g.height - 1);
    const double dx = g.dx_m[std::size_t(cam_row)], dy = g.dy_m[std::size_t(cam_row)];
    const double curv = visibility::curvature_factor(options_.curvature);
    std::vector<glm::vec3> v(std::size_t(g.width) * g.height);
    for (int r = 0; r < g.height; ++r)
        for (int c = 0; c < g.width; ++c) {
            const double e = (cam_.x - c) * dx, n = (r - cam_.y) * dy;
            const float z = g.at(c, r);
            const double up = cam_.z - (std::isnan(z) ? 0.0 : double(z)) + (e * e + n * n) * curv;
            const double len = std::sqrt(e * e + n * n + up * up);
            v[g.index(c, r)] = len > 0 ? glm::vec3(float(e / len), float(n / len), float(up / len)) : glm::vec3(0, 0, 1);
        }
    return v;
}

glm::vec3 PerspectiveView::haze(const glm::vec3& c, const glm::vec3& dir, double distance, const light::SkyTable& sky) const {
    if (!(options_.haze_distance_m > 0)) return c;
    const float t = float(std::exp(-distance / options_.haze_distance_m));
    const float hl = std::hypot(dir.x, dir.y);
    const float c_lift = std::sqrt(1 - kHorizonLift * kHorizonLift);
    const glm::vec3 horizon =
        hl > 0 ? glm::vec3(dir.x / hl * c_lift, dir.y / hl * c_lift, kHorizonLift) : glm::vec3(0, 0, 1);
    return c * t + sky.lookup(horizon) * (1 - t);
}

std::size_t PerspectiveView::hit_count() const {
    return std::size_t(std::count_if(pixels_.begin(), pixels_.end(), [](const Pixel& p) { return p.x >= 0; }));
}

void PerspectiveView::compose(const glm::vec3* radiance, const TexelSunTerm* sun_term, const light::SkyTable& sky,
                              const glm::vec3& sun_dir, const glm::vec3& sun_radiance, double sun_cos_radius,
                              std::vector<glm::vec3>& image) const {
    image.resize(pixels_.size());
    const terrain::HeightGrid& g = grid_;
    // Per-pixel sun shadows while the sun gives light.
    std::optional<PixelSunShading> pixel_sun;
    if (sun_term)
        pixel_sun.emplace(g, options_.pixel_sun_shadows ? march_.get() : nullptr, *sun_term, sun_cos_radius,
                          visibility::curvature_factor(options_.curvature));
    const bool pixel_shadows = pixel_sun && pixel_sun->marches();
    // What a ray that misses the terrain sees.
    auto sky_colour = [&](const glm::vec3& ray_dir) {
        // Below the horizon a missing ray leaves the DEM: beyond it lies more land in the haze,
        // which the sky just above the horizon stands for better than the model's dark ground.
        glm::vec3 dir = ray_dir;
        if (dir.z < kHorizonLift) {
            const float hl = std::hypot(dir.x, dir.y);
            const float c_lift = std::sqrt(1 - kHorizonLift * kHorizonLift);
            dir = hl > 0 ? glm::vec3(dir.x / hl * c_lift, dir.y / hl * c_lift, kHorizonLift) : glm::vec3(1, 0, 0);
        }
        glm::vec3 c = sky.lookup(dir);
        if (glm::dot(ray_dir, sun_dir) >= float(sun_cos_radius)) c += sun_radiance;
        return c;
    };
    // A surface's colour at a ray's hit, through the haze.
    auto surface_colour = [&](const Pixel& q) {
        glm::vec3 c(0.0f);
        if (pixel_sun) {
            c = pixel_sun->radiance(radiance, q.x, q.y, q.normal);
        } else {
            float fx = 0, fy = 0;
            const int c0 = terrain::valid_bilinear_corner(q.x, g.width, fx);
            const int r0 = terrain::valid_bilinear_corner(q.y, g.height, fy);
            const int c1 = std::min(c0 + 1, g.width - 1), r1 = std::min(r0 + 1, g.height - 1);
            c = radiance[std::size_t(r0) * g.width + c0] * ((1 - fx) * (1 - fy)) +
                radiance[std::size_t(r0) * g.width + c1] * (fx * (1 - fy)) +
                radiance[std::size_t(r1) * g.width + c0] * ((1 - fx) * fy) +
                radiance[std::size_t(r1) * g.width + c1] * (fx * fy);
        }
        if (q.transmittance < 1) {
            // Air light: the sky just above the horizon in the ray's azimuth.
            const float hl = std::hypot(q.dir.x, q.dir.y);
            const float c_lift = std::sqrt(1 - kHorizonLift * kHorizonLift);
            const glm::vec3 horizon =
                hl > 0 ? glm::vec3(q.dir.x / hl * c_lift, q.dir.y / hl * c_lift, kHorizonLift) : glm::vec3(0, 0, 1);
            c = c * q.transmittance + sky.lookup(horizon) * (1 - q.transmittance);
        }
        return c;
    };
    parallel_rows(options_.height, options_.threads, options_.width * (pixel_shadows ? 400LL : 30LL), [&](int j0, int j1) {
        for (std::size_t k = std::size_t(j0) * options_.width; k < std::size_t(j1) * options_.width; ++k) {
            const Pixel& p = pixels_[k];
            if (p.x < 0) {
                image[k] = sky_colour(p.dir);
                continue;
            }
            glm::vec3 c = surface_colour(p);
            // A silhouette pixel: the terrain over the share of its rays that hit it, the far
            // terrain behind near terrain over its own share, the sky over the rest.
            if (p.coverage < 1) {
                if (p.behind < 0) {
                    c = c * p.coverage + sky_colour(p.dir) * (1 - p.coverage);
                } else {
                    const Pixel& far = behind_[std::size_t(p.behind)];
                    const float sky_share = std::max(0.0f, 1 - p.coverage - far.coverage);
                    c = c * p.coverage + surface_colour(far) * far.coverage;
                    if (sky_share > 0) c += sky_colour(p.dir) * sky_share;
                }
            }
            image[k] = c;
        }
    });
}

}  // namespace ts::render
