// Colours by design end to end (docs/colors.md): the default map reads as the grey relief, a
// gdaldem colour table colours by height, snow only above --snow-line, and bad colour input
// stops with one line before any work.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"
#include "core/dem/read_dem.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace ts::cli_test {
namespace {

namespace fs = std::filesystem;

const std::string kLowSun = " --sun-azimuth 135 --sun-elevation 20";

double linear(unsigned char c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

struct Picture {
    int width = 0, height = 0;
    std::vector<double> r, g, b, y;  // linear
};

Picture read_picture(const fs::path& p) {
    Picture pic;
    const Pixels px = read_pixels(p);
    EXPECT_GE(px.channels, 3) << p;
    if (px.channels < 3) return pic;
    pic.width = px.width, pic.height = px.height;
    for (int r = 0; r < px.height; ++r)
        for (int c = 0; c < px.width; ++c) {
            pic.r.push_back(linear(px.at(c, r, 0))), pic.g.push_back(linear(px.at(c, r, 1)));
            pic.b.push_back(linear(px.at(c, r, 2)));
            pic.y.push_back(0.2126 * pic.r.back() + 0.7152 * pic.g.back() + 0.0722 * pic.b.back());
        }
    return pic;
}

// The shipped DEM's heights in metres (it has no voids).
std::vector<double> dem_heights() {
    const dem::Dem dem = dem::read_dem(kDem);
    EXPECT_EQ(dem.void_count(), 0u);
    return {dem.z.begin(), dem.z.end()};
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= n, mb /= n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb), saa += (a[i] - ma) * (a[i] - ma), sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

Picture render(const std::string& name, const std::string& options) {
    const fs::path out = temp_dir("colors") / (name + ".png");
    const Result r = run(ts_cmd("render " + quote(kDem) + options + " --out " + quote(out.string())));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_picture(out);
}

TEST(ColorsCli, DefaultMapReadsAsTheGreyRelief) {
    // Relief first: the default palette's map and a uniform grey terrain's under the same sun and
    // sky differ in colour, not in where it is light and dark.
    const Picture colour = render("default", kLowSun), grey = render("grey", kLowSun + " --colors grey");
    ASSERT_EQ(colour.y.size(), grey.y.size());
    const double sunlit = correlation(colour.y, grey.y);
    EXPECT_GE(sunlit, 0.97);
    const Picture colour_overcast = render("default_overcast", " --sky overcast" + kLowSun),
                  grey_overcast = render("grey_overcast", " --sky overcast --colors grey" + kLowSun);
    const double overcast = correlation(colour_overcast.y, grey_overcast.y);
    EXPECT_GE(overcast, 0.9);
    std::printf("luminance correlation, default palette vs grey: sunlit %.4f, overcast %.4f\n", sunlit, overcast);
}

TEST(ColorsCli, AColourTableColoursByHeight) {
    // Green at the lowest height, red at the highest (percent stops), in gdaldem's format.
    const fs::path table = temp_dir("colors") / "green_red.txt";
    std::ofstream(table) << "# low green, high red\n0% 0 200 0\n100%,200,0,0\nnv 0 0 0 0\n";
    const Picture p = render("table", kLowSun + " --colors " + quote(table.string()));
    const std::vector<double> z = dem_heights();
    ASSERT_EQ(z.size(), p.r.size());
    std::vector<double> redness(z.size());
    for (std::size_t i = 0; i < z.size(); ++i) redness[i] = (p.r[i] - p.g[i]) / (p.r[i] + p.g[i] + 1e-6);
    EXPECT_GT(correlation(redness, z), 0.8);  // 0.86: shading and the sRGB ramp make it less than 1
}

TEST(ColorsCli, SnowOnlyAboveTheSnowLine) {
    const Picture plain = render("no_snow", kLowSun), winter = render("snow", kLowSun + " --snow-line 2000");
    const std::vector<double> z = dem_heights();
    double high_plain = 0, high_winter = 0, low_plain = 0, low_winter = 0;
    int high = 0, low = 0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        if (z[i] > 2200) high_plain += plain.y[i], high_winter += winter.y[i], ++high;
        if (z[i] < 1800) low_plain += plain.y[i], low_winter += winter.y[i], ++low;
    }
    ASSERT_GT(high, 100);
    // Above the line the ground is snow (albedo 0.8 against ~0.2), so brighter even after the
    // picture's exposure adapts; below it, darker for that exposure only, never whiter.
    EXPECT_GT(high_winter / high, 1.8 * high_plain / high);
    EXPECT_LE(low_winter / low, 1.01 * low_plain / low);
}

TEST(ColorsCli, BadColourInputIsOneLineBeforeAnyWork) {
    const fs::path dir = temp_dir("colors_bad");
    const fs::path bad = dir / "bad.txt";
    std::ofstream(bad) << "0 10 20 30\n1000 brown\n";
    const std::string out = kLowSun + " --out " + quote((dir / "x.png").string());
    for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
             {"render " + quote(kDem) + " --colors rainbow" + out, "--colors rainbow: neither a built-in palette"},
             {"render " + quote(kDem) + " --colors " + quote(bad.string()) + out, "bad.txt: line 2: give HEIGHT R G B"},
             {"render " + quote(kDem) + " --materials rule" + out, "--materials rule: materials are no longer guessed"},
             {"render " + quote(kDem) + " --snow-line 20000" + out, "--snow-line: must be within"},
             {"tiles " + quote(kDem) + " --zoom 8 --style relief --colors grey --out " + quote((dir / "t").string()),
              "--colors and --snow-line colour --style color"}}) {
        const Result r = run(ts_cmd(args));
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    EXPECT_FALSE(fs::exists(dir / "t"));
}

TEST(ColorsCli, ColourTilesRecordTheirPalette) {
    const fs::path dir = temp_dir("colors_tiles");
    const fs::path grey = dir / "grey", hyps = dir / "hyps";
    ASSERT_EQ(run(ts_cmd("tiles " + quote(kDem) + " --zoom 8 --style color --colors grey --out " + quote(grey.string())))
                  .exit_code,
              0);
    std::ifstream job(grey / ".terrashade-tiles.json");
    std::stringstream text;
    text << job.rdbuf();
    // The palette as fitted to the DEM's heights (one grey from its lowest height).
    EXPECT_NE(text.str().find(" 190 190 190\""), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("\"colors\":\""), std::string::npos) << text.str();
    // Another palette into the same folder is another job: refused without --overwrite.
    const Result again = run(ts_cmd("tiles " + quote(kDem) + " --zoom 8 --style color --out " + quote(grey.string())));
    EXPECT_EQ(again.exit_code, 2) << again.err;
}

}  // namespace
}  // namespace ts::cli_test
