// `terrashade render --mesh`: the Cessna over a crop of the Grenoble DEM at low sun darkens the
// terrain on the side away from the sun and nowhere else; bad mesh flags exit 2 with one line
// before any heavy work.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"
#include "tests/support/shared_data.hpp"

namespace ts::cli_test {
namespace {

using ts::test::kCessna;
// Low sun in the south-east, a fixed exposure so the two pictures compare code for code.
const std::string kLight = " --sun-azimuth 135 --sun-elevation 15 --exposure 13";

struct Image {
    int w = 0, h = 0, channels = 0;
    std::vector<unsigned char> px;
};

Image read_png(const std::filesystem::path& p) {
    Pixels px = read_pixels(p);
    EXPECT_GT(px.width, 0) << p;
    Image img;
    img.w = px.width, img.h = px.height, img.channels = px.channels;
    img.px = std::move(px.data);
    return img;
}

TEST(RenderMeshCli, TheCessnasShadowDarkensTheTerrainAwayFromTheSun) {
    ASSERT_TRUE(std::filesystem::exists(kCessna)) << "the shared meshes are missing: " << kCessna;
    const auto dir = temp_dir("render_mesh");
    const auto plain = dir / "plain.png", with = dir / "with.png";
    const Result a = run(ts_cmd("render " + quote(kDem) + kCrop + kLight + " --out " + quote(plain.string())));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const Result b = run(ts_cmd("render " + quote(kDem) + kCrop + kLight + " --mesh " + quote(kCessna) +
                                " --at 5.75,45.20,400agl --hpr 45,0,0 --scale 60 --spheres 32 --sphere-cache-dir " +
                                quote((dir / "cache").string()) + " --out " + quote(with.string())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.out.find("mesh "), std::string::npos) << b.out;
    const Image p = read_png(plain), m = read_png(with);
    ASSERT_EQ(p.px.size(), m.px.size());
    // The mesh's anchor is the crop's centre texel; the shadow of a sun in the south-east falls
    // to the north-west of it.
    const double cx = p.w / 2.0, cy = p.h / 2.0;
    double sx = 0, sy = 0, weight = 0;
    int brighter = 0;
    for (int r = 0; r < p.h; ++r)
        for (int c = 0; c < p.w; ++c) {
            double drop = 0;
            for (int k = 0; k < p.channels; ++k) {
                const std::size_t i = (std::size_t(r) * p.w + c) * p.channels + k;
                drop += double(p.px[i]) - double(m.px[i]);
                if (m.px[i] > p.px[i] + 1) ++brighter;
            }
            if (drop > 3 * 10) sx += (c + 0.5 - cx) * drop, sy += (r + 0.5 - cy) * drop, weight += drop;
        }
    ASSERT_GT(weight, 0.0) << "no texel darkened by the mesh";
    sx /= weight, sy /= weight;
    std::printf("shadow centroid %.1f texels east, %.1f texels south of the mesh\n", sx, sy);
    EXPECT_LT(sx, 0.0);  // west
    EXPECT_LT(sy, 0.0);  // north (rows grow southwards)
    EXPECT_EQ(brighter, 0);
}

// The sun shadow cast by the Cessna's triangles (the default) lies inside the one its spheres
// cast, and is smaller: the spheres bound the mesh, their union is thicker than its wings.
TEST(RenderMeshCli, TheTrianglesSunShadowLiesInsideTheSpheresAndIsSmaller) {
    const auto dir = temp_dir("render_mesh_caster");
    const auto plain = dir / "plain.png", tri = dir / "tri.png", sph = dir / "sph.png";
    // A Cessna x250 (a 2.8 km span, ~100 pixels) under a 45-degree sun.
    const std::string light = " --sun-azimuth 135 --sun-elevation 45 --exposure 13";
    const std::string mesh = " --mesh " + quote(kCessna) + " --at 5.75,45.20,800agl --hpr 45,0,0 --scale 250 --spheres 32 "
                             "--sphere-cache-dir " + quote((dir / "cache").string());
    ASSERT_EQ(run(ts_cmd("render " + quote(kDem) + kCrop + light + " --out " + quote(plain.string()))).exit_code, 0);
    const Result a = run(ts_cmd("render " + quote(kDem) + kCrop + light + mesh + " --out " + quote(tri.string())));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const Result b = run(ts_cmd("render " + quote(kDem) + kCrop + light + mesh + " --mesh-sun-shadow spheres --out " +
                                quote(sph.string())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const Image p = read_png(plain), t = read_png(tri), s = read_png(sph);
    ASSERT_EQ(p.px.size(), t.px.size());
    ASSERT_EQ(p.px.size(), s.px.size());
    // A pixel in the sun shadow: darker than without the mesh by more than the sky's faint
    // darkening (a shadowed pixel loses its direct sun: tens of codes).
    auto shadowed = [&](const Image& m, std::size_t px) {
        double drop = 0;
        for (int k = 0; k < p.channels; ++k) drop += double(p.px[px * p.channels + k]) - double(m.px[px * p.channels + k]);
        return drop > 3 * 25;
    };
    long in_t = 0, in_s = 0, t_outside_s = 0;
    for (std::size_t px = 0; px < std::size_t(p.w) * p.h; ++px) {
        const bool a_t = shadowed(t, px), a_s = shadowed(s, px);
        in_t += a_t, in_s += a_s, t_outside_s += a_t && !a_s;
    }
    std::printf("sun shadow pixels: %ld cast by the triangles, %ld by the spheres, %ld of the first outside the second\n",
                in_t, in_s, t_outside_s);
    EXPECT_GT(in_t, 20);
    EXPECT_LT(in_t, in_s * 8 / 10);
    EXPECT_LE(t_outside_s, in_t / 50);
}

// The covered-pixel count `render` prints for the meshes drawn in a perspective view.
long covered_pixels(const std::string& out) {
    const std::string key = "meshes cover ";
    const auto at = out.find(key);
    return at == std::string::npos ? -1 : std::stol(out.substr(at + key.size()));
}

TEST(RenderMeshCli, APerspectiveViewDrawsTheCessnaAndHidesOneBelowTheTerrain) {
    const auto dir = temp_dir("render_mesh_view");
    const auto plain = dir / "plain.png", with = dir / "with.png", buried = dir / "buried.png";
    const std::string view = " --view perspective --camera 5.70,45.17,1200,40,-10,40 --size 320x180";
    const std::string cache = " --sphere-cache-dir " + quote((dir / "cache").string());
    const Result a = run(ts_cmd("render " + quote(kDem) + kCrop + kLight + view + " --out " + quote(plain.string())));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const Result b = run(ts_cmd("render " + quote(kDem) + kCrop + kLight + view + " --mesh " + quote(kCessna) +
                                " --at 5.75,45.20,400agl --hpr 45,0,0 --scale 60 --spheres 32" + cache + " --out " +
                                quote(with.string())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.out.find("drawn lit per vertex"), std::string::npos) << b.out;
    const long covered = covered_pixels(b.out);
    EXPECT_GT(covered, 30) << b.out;
    const Image p = read_png(plain), m = read_png(with);
    ASSERT_EQ(p.px.size(), m.px.size());
    long changed = 0;
    for (std::size_t i = 0; i < p.px.size(); i += std::size_t(p.channels)) {
        int d = 0;
        for (int k = 0; k < p.channels; ++k) d = std::max(d, std::abs(int(p.px[i + k]) - int(m.px[i + k])));
        changed += d > 8;
    }
    std::printf("aircraft: %ld pixels covered, %ld pixels changed by more than 8 codes\n", covered, changed);
    // The aircraft's pixels and its shadows, not the whole picture.
    EXPECT_GE(changed, covered / 2);
    EXPECT_LT(changed, long(p.w) * p.h / 4);
    // 300 m under the terrain: a warning, a picture, no mesh pixel shown.
    const Result c = run(ts_cmd("render " + quote(kDem) + kCrop + kLight + view + " --mesh " + quote(kCessna) +
                                " --at 5.75,45.20,-300agl --scale 60 --spheres 32" + cache + " --out " +
                                quote(buried.string())));
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_NE(c.err.find("below the terrain"), std::string::npos) << c.err;
    EXPECT_EQ(covered_pixels(c.out), 0) << c.out;
}

// The centroid (texels from the picture's centre) of where `with` is darker than `plain`.
bool shadow_centroid(const Image& plain, const Image& with, double& x, double& y) {
    double sx = 0, sy = 0, weight = 0;
    for (int r = 0; r < plain.h; ++r)
        for (int c = 0; c < plain.w; ++c) {
            double drop = 0;
            for (int k = 0; k < plain.channels; ++k) {
                const std::size_t i = (std::size_t(r) * plain.w + c) * plain.channels + k;
                drop += double(plain.px[i]) - double(with.px[i]);
            }
            if (drop > 3 * 6) sx += (c + 0.5 - plain.w / 2.0) * drop, sy += (r + 0.5 - plain.h / 2.0) * drop, weight += drop;
        }
    if (weight <= 0) return false;
    x = sx / weight, y = sy / weight;
    return true;
}

// relight --mesh-path: the Cessna flies south-west to north-east over the crop; each frame's
// shadow (against the same frames without it) lies further north-east than the last.
TEST(RenderMeshCli, RelightMeshPathMovesTheShadowAlongThePath) {
    const auto dir = temp_dir("relight_mesh_path");
    const auto path = dir / "path.csv";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_TRUE(f);
        std::fprintf(f, "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n0,5.70,45.15,700,45,0,0\n"
                        "7200,5.80,45.25,700,45,0,0\n");
        std::fclose(f);
    }
    const std::string times = " --times 2025-06-21T10:00:00Z/2025-06-21T12:00:00Z/PT1H --directions 8 --exposure 13";
    const std::string cache = " --sphere-cache-dir " + quote((dir / "cache").string());
    const Result a = run(ts_cmd("relight " + quote(kDem) + kCrop + times + " --out " + quote((dir / "plain").string())));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const Result b = run(ts_cmd("relight " + quote(kDem) + kCrop + times + " --mesh " + quote(kCessna) + " --mesh-path " +
                                quote(path.string()) + " --scale 80 --spheres 32" + cache + " --out " +
                                quote((dir / "moving").string())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.out.find("a frame recomputing"), std::string::npos) << b.out;
    std::vector<std::filesystem::path> frames;
    for (const auto& e : std::filesystem::directory_iterator(dir / "moving"))
        if (e.path().extension() == ".png") frames.push_back(e.path().filename());
    std::sort(frames.begin(), frames.end());
    ASSERT_EQ(frames.size(), 3u);
    double last_x = -1e9, last_y = 1e9;
    for (const auto& name : frames) {
        double x = 0, y = 0;
        ASSERT_TRUE(shadow_centroid(read_png(dir / "plain" / name), read_png(dir / "moving" / name), x, y)) << name;
        std::printf("%s: shadow centroid %.1f texels east, %.1f texels south of the centre\n", name.c_str(), x, y);
        EXPECT_GT(x, last_x + 5) << name;  // east
        EXPECT_LT(y, last_y - 5) << name;  // north
        last_x = x, last_y = y;
    }
    // Bad uses: one line, exit 2, before any frame.
    const std::string base = "relight " + quote(kDem) + kCrop + times + " --out " + quote((dir / "bad").string());
    const std::vector<std::string> cases = {
        " --mesh-path " + quote(path.string()),                                                    // no --mesh
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,100 --mesh-path " + quote(path.string()),   // --at for it
        " --mesh " + quote(kCessna) + " --mesh-path /no/such/path.csv",
        " --mesh " + quote(kCessna) + " --mesh-path " + quote(path.string()) +
            " --view perspective --camera 5.70,45.17,1200,40,-10,40",
    };
    for (const std::string& c : cases) {
        const Result r = run(ts_cmd(base + c));
        EXPECT_EQ(r.exit_code, 2) << c << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c << "\n" << r.err;
    }
    // A path that leaves the DEM.
    const auto off = dir / "off.csv";
    {
        std::FILE* f = std::fopen(off.c_str(), "w");
        ASSERT_TRUE(f);
        std::fprintf(f, "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n0,5.70,45.15,700,45,0,0\n"
                        "60,7.80,45.25,700,45,0,0\n");
        std::fclose(f);
    }
    const Result r = run(ts_cmd(base + " --mesh " + quote(kCessna) + " --mesh-path " + quote(off.string())));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad" / "times.csv"));
}

TEST(RenderMeshCli, BadMeshFlagsExitTwoWithOneLine) {
    const auto dir = temp_dir("render_mesh_bad");
    const std::string out = " --out " + quote((dir / "x.png").string());
    const std::string base = "render " + quote(kDem) + kCrop + kLight + out;
    const std::vector<std::string> cases = {
        " --mesh /no/such/mesh.ac --at 5.75,45.2,100",
        " --mesh " + quote(kCessna) + " --at 5.75,45.2",
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,1x0agl",
        " --mesh " + quote(kCessna),
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,100 --scale -2",
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,100 --spheres 4",
        " --mesh " + quote(kCessna) + " --at 7.5,45.2,100",  // off the DEM
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,100 --hpr 10,20",
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,100 --mesh-sun-shadow blobs",
        " --mesh " + quote(kCessna) + " --at 5.75,45.2,100 --mesh-sun-rays 0",
    };
    for (const std::string& c : cases) {
        const Result r = run(ts_cmd(base + c));
        EXPECT_EQ(r.exit_code, 2) << c << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << c;
    }
}

}  // namespace
}  // namespace ts::cli_test
