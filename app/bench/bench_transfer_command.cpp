// `terrashade bench transfer DEM`: the transfer stage (core/render/transfer.hpp) on the CPU and
// on the GPU (gpu/render) in one run: the exponentiation T = exp(V + F) of every texel, and the
// per-frame relight rgb = T . L, with per-stage milliseconds, Mpx/s, their CPU/GPU ratios and
// the two paths' agreement. The log-SH visibility it starts from is computed first (on the GPU
// when there is one) and is not part of the measurement.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "app/options/within_range.hpp"
#include "app/io_plan.hpp"
#include "app/bench/bench_command.hpp"
#include "app/bench/error_stats.hpp"
#include "app/dem_input.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/render/transfer.hpp"
#include "core/sh/exp_method.hpp"
#include "core/material/log_brdf.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/visibility_grid.hpp"

#ifdef TERRASHADE_HAS_GPU
#include "gpu/context.hpp"
#include "gpu/render/gpu_transfer.hpp"
#include "gpu/visibility/gpu_visibility.hpp"
#endif

namespace ts::app {
namespace {

struct BenchTransferOptions {
    DemInput dem;
    int directions = 32;
    int frames = 10;
    int threads = 0;
    std::string lobe = "diffuse";
    double phong_alpha = 20.0;
    bool cpu_only = false;
    std::optional<std::uint32_t> device;
    std::string exp_method = "hybrid";  // hybrid or scaling_squaring (both run on the GPU)
};

// A sky-like light for the relight frames: bright zenith, a warm side, some higher-band detail.
std::array<glm::vec3, 16> frame_light(int frame) {
    std::array<glm::vec3, 16> l{};
    const float a = 0.3f * float(frame);
    l[0] = glm::vec3(2.0f, 2.6f, 3.4f);
    l[1] = glm::vec3(0.4f * std::sin(a));
    l[2] = glm::vec3(1.1f, 1.2f, 1.4f);
    l[3] = glm::vec3(0.4f * std::cos(a), 0.3f * std::cos(a), 0.2f * std::cos(a));
    for (int i = 4; i < 16; ++i) l[std::size_t(i)] = glm::vec3(0.05f * float((i + frame) % 5) - 0.1f);
    return l;
}

struct TransferRow {
    std::string stage;
    double cpu_ms = NAN, gpu_ms = NAN;
};

void print_rows(const std::vector<TransferRow>& rows, double texels) {
    std::printf("%-40s %10s %10s %9s %11s %11s\n", "stage", "CPU ms", "GPU ms", "CPU/GPU", "CPU Mpx/s", "GPU Mpx/s");
    auto cell = [](double v, const char* fmt) {
        char buf[32];
        if (std::isnan(v)) return std::string("-");
        std::snprintf(buf, sizeof buf, fmt, v);
        return std::string(buf);
    };
    for (const TransferRow& r : rows) {
        const double ratio = r.cpu_ms / r.gpu_ms;
        std::printf("%-40s %10s %10s %9s %11s %11s\n", r.stage.c_str(), cell(r.cpu_ms, "%.2f").c_str(),
                    cell(r.gpu_ms, "%.2f").c_str(), cell(ratio, "%.2f").c_str(),
                    cell(texels / r.cpu_ms / 1e3, "%.2f").c_str(), cell(texels / r.gpu_ms / 1e3, "%.2f").c_str());
    }
}

double stage_ms(const auto& stages, const std::string& label) {
    for (const auto& s : stages)
        if (s.label == label) return s.ms;
    return NAN;
}

void run_bench_transfer(const BenchTransferOptions& o) {
    if (o.frames < 1) throw InputError("--frames: must be >= 1");
    if (o.lobe != "diffuse" && o.lobe != "phong") throw InputError("--lobe: diffuse or phong, got " + o.lobe);
    IoPlan plan;
    plan.inputs("DEM", o.dem.files);
    plan.check();
    const dem::Dem dem = load_dem_input(o.dem);
    const visibility::VisibilityGrid vgrid(dem);
    const terrain::HeightGrid& grid = vgrid.view();
    const std::size_t texels = std::size_t(grid.width) * std::size_t(grid.height);
    const int threads = thread_count(o.threads);

#ifdef TERRASHADE_HAS_GPU
    std::unique_ptr<gpu::Context> context;
    if (!o.cpu_only) {
        try {
            context = std::make_unique<gpu::Context>(gpu::ContextOptions{.device_index = o.device});
        } catch (const std::exception& e) {
            if (o.device) throw;
            std::fprintf(stderr, "terrashade: warning: no usable Vulkan device, CPU only (%s)\n", e.what());
        }
    }
#endif

    // The input: log-SH visibility (exact horizons), normals, the lobe.
    std::vector<float> log_vis;
    const Stopwatch t_vis;
    std::string vis_where = "CPU";
    visibility::HorizonOptions ho;
    ho.method = visibility::HorizonMethod::exact;
    ho.directions = o.directions;
    ho.threads = o.threads;
#ifdef TERRASHADE_HAS_GPU
    if (context) {
        gpu::visibility::Options go;
        go.horizon = ho;
        go.sky = false;
        const auto r = gpu::visibility::compute(*context, grid, go);
        log_vis.assign(r.log_sh.begin(), r.log_sh.end());
        vis_where = "GPU";
    }
#endif
    if (log_vis.empty()) log_vis = visibility::log_sh_raster(visibility::compute_horizons(grid, ho), visibility::kDefaultVisibilityLogEps, o.threads);
    const double vis_ms = t_vis.milliseconds();

    const render::NormalField normals = render::terrain_normals(grid, o.threads);
    std::vector<float> axis(3 * texels);
    for (std::size_t t = 0; t < texels; ++t) {
        glm::vec3 n(normals.x[t], normals.y[t], normals.z[t]);
        if (o.lobe == "phong") n = 2.0f * n.z * n - glm::vec3(0, 0, 1);  // mirror of a view from above
        axis[3 * t] = n.x;
        axis[3 * t + 1] = n.y;
        axis[3 * t + 2] = n.z;
    }
    const sh::LogBrdfTable table;
    const sh::ZhVec zh = o.lobe == "phong" ? table.phong(o.phong_alpha) : table.diffuse();
    const std::array<float, 4> lobe_zh = {float(zh[0]), float(zh[1]), float(zh[2]), float(zh[3])};
    render::TransferInputs in;
    in.texels = texels;
    in.log_visibility = log_vis.data();
    in.lobe_axis = axis.data();
    in.lobe_log_zh = lobe_zh.data();
    in.uniform_lobe = true;
    in.threads = o.threads;
    in.method = sh::parse_exp_method(o.exp_method);

    std::printf("bench transfer: %s, %d x %d = %.3f M texels, %s lobe, %s exponentiation, %d CPU thread%s\n",
                dem.source.c_str(), grid.width, grid.height, double(texels) / 1e6, o.lobe.c_str(),
                o.exp_method.c_str(), threads,
                threads == 1 ? "" : "s");
    std::printf("input: log-SH visibility (exact, %d directions, %s) in %.0f ms, not measured below\n\n",
                o.directions, vis_where.c_str(), vis_ms);

    // CPU.
    std::vector<float> t_cpu(16 * texels);
    Stopwatch t0;
    render::transfer_vectors(in, t_cpu.data());
    const double cpu_transfer_ms = t0.milliseconds();
    std::vector<glm::vec3> rgb_cpu(texels);
    render::shade_transfer(t_cpu.data(), texels, frame_light(0), rgb_cpu.data(), o.threads);  // warm-up
    double cpu_shade_ms = INFINITY;
    for (int f = 0; f < o.frames; ++f) {
        t0.restart();
        render::shade_transfer(t_cpu.data(), texels, frame_light(f), rgb_cpu.data(), o.threads);
        cpu_shade_ms = std::min(cpu_shade_ms, t0.milliseconds());
    }
    // Frame 0's light again, for the agreement check below.
    render::shade_transfer(t_cpu.data(), texels, frame_light(0), rgb_cpu.data(), o.threads);

    std::vector<TransferRow> rows;
#ifdef TERRASHADE_HAS_GPU
    if (context) {
        t0.restart();
        gpu::render::TransferField field(*context, in);
        const double gpu_build_ms = t0.milliseconds();  // includes the two pipelines' compilation
        const auto build = field.stages();
        const double gpu_compute_wall = field.wall_ms();
        std::vector<float> t_gpu(16 * texels);
        field.download(t_gpu.data());
        const double download_ms = stage_ms(field.stages(), "download");
        const double download_wall = field.wall_ms();
        std::vector<glm::vec3> rgb_gpu(texels);
        field.shade(frame_light(0), rgb_gpu.data());  // warm-up
        double best_wall = INFINITY;
        std::vector<gpu::render::StageTime> best;
        for (int f = 0; f < o.frames; ++f) {
            field.shade(frame_light(f), rgb_gpu.data());
            if (field.wall_ms() < best_wall) best_wall = field.wall_ms(), best = field.stages();
        }
        field.shade(frame_light(0), rgb_gpu.data());

        rows.push_back({"transfer: upload V, axes", NAN, stage_ms(build, "upload")});
        rows.push_back({"transfer: exp(V + F) (kernel)", cpu_transfer_ms, stage_ms(build, "transfer")});
        rows.push_back({"transfer: download T", NAN, download_ms});
        rows.push_back({"transfer: total (wall)", cpu_transfer_ms, gpu_compute_wall + download_wall});
        rows.push_back({"shade: upload light", NAN, stage_ms(best, "light")});
        rows.push_back({"shade: T . L, 48 MAC/texel (kernel)", cpu_shade_ms, stage_ms(best, "shade")});
        rows.push_back({"shade: download rgb", NAN, stage_ms(best, "download")});
        rows.push_back({"shade: frame (wall, best of " + std::to_string(o.frames) + ")", cpu_shade_ms, best_wall});
        print_rows(rows, double(texels));
        std::printf("(GPU: %s; device times from its timestamps; pipeline creation and first upload %.0f ms "
                    "beyond the stages)\n",
                    context->device_info().name.c_str(), gpu_build_ms - gpu_compute_wall);

        // Agreement of the two paths.
        double worst_t = 0, worst_rgb = 0;
        std::size_t beyond = 0;
        for (std::size_t t = 0; t < texels; ++t) {
            std::array<double, 16> c, g;  // the texel's T on each path ([coefficient][texel] planes)
            double norm = 0;
            for (std::size_t i = 0; i < 16; ++i) {
                c[i] = t_cpu[i * texels + t], g[i] = t_gpu[i * texels + t];
                norm += c[i] * c[i];
            }
            if (std::isnan(norm)) continue;
            const double rel = bench::max_abs_difference(c, g) / std::max(std::sqrt(norm), 1e-30);
            if (rel > 1e-4) ++beyond;
            else worst_t = std::max(worst_t, rel);
            const std::array<double, 3> ref = {rgb_cpu[t].x, rgb_cpu[t].y, rgb_cpu[t].z};
            const std::array<double, 3> got = {rgb_gpu[t].x, rgb_gpu[t].y, rgb_gpu[t].z};
            worst_rgb = std::max(worst_rgb, bench::max_relative_error(got, ref, 1e-6));
        }
        std::printf("agreement: T within %.1e of each texel's norm (%zu texels beyond 1e-4), rgb within %.1e "
                    "relative\n",
                    worst_t, beyond, worst_rgb);
        return;
    }
#endif
    rows.push_back({"transfer: exp(V + F)", cpu_transfer_ms, NAN});
    rows.push_back({"shade: T . L, 48 MAC/texel (best of " + std::to_string(o.frames) + ")", cpu_shade_ms, NAN});
    print_rows(rows, double(texels));
}

}  // namespace

void add_bench_transfer_command(CLI::App& bench) {
    auto o = std::make_shared<BenchTransferOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "transfer", "Transfer stage (SH exponentiation + relight dot product) on CPU and GPU: ms, Mpx/s, ratios");
    add_dem_input_options(*cmd, o->dem);
    cmd->add_option("--directions", o->directions, "Azimuths of the input visibility")
        ->capture_default_str()
        ->check(within(4, 2048));
    cmd->add_option("--frames", o->frames, "Relight frames timed (the best is reported)")
        ->capture_default_str()
        ->check(within(1, 10000));
    cmd->add_option("--lobe", o->lobe, "diffuse (cos/pi at the normal) or phong (at the mirror of a nadir view)")
        ->capture_default_str();
    cmd->add_option("--phong-alpha", o->phong_alpha, "Phong exponent for --lobe phong")
        ->capture_default_str()
        ->check(within(1.0, 1000.0));
    cmd->add_option("--threads", o->threads, "CPU worker threads (0 = one per core)")->capture_default_str();
    cmd->add_flag("--cpu", o->cpu_only, "CPU path only");
    cmd->add_option("--device", o->device, "Vulkan device index (terrashade devices)");
    cmd->add_option("--exp-method", o->exp_method, "SH exponentiation (both run on the GPU)")
        ->capture_default_str()
        ->check(CLI::IsMember({"hybrid", "scaling_squaring"}));
    cmd->callback([o] { run_bench_transfer(*o); });
}

}  // namespace ts::app
