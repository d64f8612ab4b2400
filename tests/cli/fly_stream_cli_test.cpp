// `terrashade fly` streaming a DEM larger than this machine could fly whole: `bench dem` writes a
// synthetic SRTM1-like mosaic band by band, `fly --memory-budget 1024` renders three frames of it
// in a child whose peak RSS is measured, and `--stream off` on the same file is refused at once
// instead of shading tens of gigabytes. Also `bench dem`'s file itself: its tags, and heights
// equal to the one definition of the noise (app/bench/synthetic_mosaic.cpp), and its bad flags.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <tiffio.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/bench/study/synthetic_mosaic.hpp"
#include "cli_support.hpp"
#include "frame_pixels.hpp"
#include "core/dem/dem_source.hpp"
#include "core/dem/read_dem.hpp"
#include "core/raster/tiff_file.hpp"

namespace ts::cli_test {
namespace {

// gpu::whole_fly_bytes is 250 bytes a texel: 10241^2 texels take 26.2 GB flown whole, more than
// this machine's 25.3 GB (24 GiB) in all, and stream in ~7 s within 1 GB. (8193^2, 16.8 GB, is
// less than the ~24 GB an idle one has available: --stream off would be let through there.)
constexpr int kSide = 10241;
constexpr double kWholeFlyBytesPerTexel = 250;
constexpr double kPeakRssLimitBytes = 1.6e9;

// A private directory per test, removed when the test ends, passed or failed: the big DEM
// does not outlive its test.
class FlyStreamCli : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = temp_dir(std::string("fly_stream_") + info->name());
    }
    void TearDown() override {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
        EXPECT_FALSE(std::filesystem::exists(dir_)) << dir_;
    }
    std::filesystem::path dir_;
};

struct Measured {
    int exit_code = -1;
    bool timed_out = false;
    std::string out, err;
    double peak_rss_bytes = 0, seconds = 0;
};

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs terrashade with `args` as a direct child (no shell between: wait4's peak RSS is this
// command's alone, not a shell's nor an earlier child's), stdout and stderr to files in `dir`,
// `env` added to its environment. Killed after `timeout_s`: a refusal that regressed must not
// shade 26 GB.
Measured run_measured(const std::vector<std::string>& args, const std::filesystem::path& dir, double timeout_s,
                      const std::vector<std::string>& env = {}) {
    static int counter = 0;
    const auto out_path = dir / ("out" + std::to_string(counter)), err_path = dir / ("err" + std::to_string(counter));
    ++counter;
    std::vector<std::string> argv_s = {terrashade()};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    // The environment is built here: after fork only async-signal-safe calls (no putenv).
    std::vector<std::string> env_s = env;
    for (char** e = environ; *e; ++e) {
        const std::string kv = *e;
        const bool replaced = std::any_of(env.begin(), env.end(), [&](const std::string& add) {
            return kv.compare(0, add.find('=') + 1, add, 0, add.find('=') + 1) == 0;
        });
        if (!replaced) env_s.push_back(kv);
    }
    std::vector<char*> envp;
    for (auto& kv : env_s) envp.push_back(kv.data());
    envp.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int o = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0) ::_exit(127);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    Measured m;
    if (pid < 0) return m;
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout_s) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            m.timed_out = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    m.peak_rss_bytes = double(usage.ru_maxrss) * 1024.0;  // kilobytes on Linux
    m.out = read_text(out_path), m.err = read_text(err_path);
    return m;
}

// frames.csv's rows as name -> value maps.
std::vector<std::vector<std::pair<std::string, double>>> read_frames_csv(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::string line;
    std::vector<std::string> names;
    std::vector<std::vector<std::pair<std::string, double>>> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
        if (names.empty()) {
            names = cells;
            continue;
        }
        std::vector<std::pair<std::string, double>> row;
        for (std::size_t i = 0; i < cells.size() && i < names.size(); ++i)
            row.emplace_back(names[i], std::atof(cells[i].c_str()));
        rows.push_back(row);
    }
    return rows;
}

double column(const std::vector<std::pair<std::string, double>>& row, const std::string& name) {
    for (const auto& [n, v] : row)
        if (n == name) return v;
    ADD_FAILURE() << "frames.csv has no column " << name;
    return -1;
}

// MemTotal of /proc/meminfo, bytes (0 if unknown).
double machine_memory_bytes() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kb = 0;
    while (in >> key >> kb) {
        if (key == "MemTotal:") return kb * 1024.0;
        in.ignore(1 << 10, '\n');
    }
    return 0;
}

int count_lines(const std::string& s) {
    return int(std::count(s.begin(), s.end(), '\n'));
}

TEST_F(FlyStreamCli, ALargerDemThanMemoryIsFlownWithinTheBudget) {
    const auto dem = dir_ / "big.tif";
    const double whole_bytes = kWholeFlyBytesPerTexel * double(kSide) * double(kSide);
    ASSERT_GT(whole_bytes, 16e9);
    const Measured gen = run_measured({"bench", "dem", std::to_string(kSide), "--out", dem.string()}, dir_, 120);
    ASSERT_EQ(gen.exit_code, 0) << gen.err;
    ASSERT_TRUE(std::filesystem::exists(dem));
    const auto file_bytes = std::filesystem::file_size(dem);
    std::printf("bench dem %d: %.1f MB in %.1f s, peak RSS %.0f MB; flown whole it would take %.1f GB\n", kSide,
                double(file_bytes) / 1e6, gen.seconds, gen.peak_rss_bytes / 1e6, whole_bytes / 1e9);
    // Band by band: the generator never holds the grid (2 bytes a texel, 210 MB here).
    EXPECT_LT(gen.peak_rss_bytes, 150e6);
    // The last band and column of tiles are partial: the far corner reads back as the noise.
    {
        const dem::DemSource source({dem});
        ASSERT_EQ(source.layout().width, kSide);
        ASSERT_EQ(source.layout().height, kSide);
        std::vector<float> z;
        source.read(kSide - 40, kSide - 40, 40, 40, z);
        for (int r = 0; r < 40; ++r)
            for (int c = 0; c < 40; ++c)
                ASSERT_EQ(z[std::size_t(r) * 40 + std::size_t(c)],
                          std::round(app::synthetic_height(kSide - 40 + c, kSide - 40 + r)));
    }

    const auto out = dir_ / "frames";
    const Measured fly = run_measured(
        {"fly", dem.string(), "--memory-budget", "1024", "--frames", "3", "--size", "480x270", "--out", out.string()},
        dir_, 180);
    std::printf("fly --memory-budget 1024 --frames 3: %.1f s, peak RSS %.0f MB\n%s", fly.seconds,
                fly.peak_rss_bytes / 1e6, fly.out.c_str());
    ASSERT_EQ(fly.exit_code, 0) << fly.err;
    EXPECT_NE(fly.out.find("streaming"), std::string::npos) << fly.out;
    EXPECT_LT(fly.peak_rss_bytes, kPeakRssLimitBytes)
        << "the streamed flight held " << fly.peak_rss_bytes / 1e6 << " MB";
    const auto rows = read_frames_csv(out / "frames.csv");
    ASSERT_EQ(rows.size(), 3u);
    for (const auto& row : rows) {
        EXPECT_EQ(column(row, "coarse_fallbacks"), 0) << "offscreen frames wait for their tiles";
        EXPECT_GT(column(row, "tiles_resident"), 0) << "no detail tile was streamed in";
    }
    std::vector<std::vector<unsigned char>> frames;
    for (int i = 0; i < 3; ++i) {
        int w = 0, h = 0;
        frames.push_back(read_rgb(out / ("frame_000" + std::to_string(i) + ".png"), w, h));
        ASSERT_EQ(w, 480);
        ASSERT_EQ(h, 270);
        const auto& px = frames.back();
        double mean = 0;
        for (unsigned char v : px) mean += v;
        mean /= double(px.size());
        EXPECT_GT(mean, 30.0) << "frame " << i << " is black";
        // Terrain fills the lower half: not one flat colour.
        double lo = 255, hi = 0;
        for (std::size_t k = px.size() / 6 * 3; k < px.size(); k += 3)
            lo = std::min<double>(lo, px[k]), hi = std::max<double>(hi, px[k]);
        EXPECT_GT(hi - lo, 40.0) << "frame " << i << " shows no relief";
    }
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
            double diff = 0;
            for (std::size_t k = 0; k < frames[std::size_t(i)].size(); ++k)
                diff += std::abs(int(frames[std::size_t(i)][k]) - int(frames[std::size_t(j)][k]));
            EXPECT_GT(diff / double(frames[std::size_t(i)].size()), 2.0)
                << "frames " << i << " and " << j << " are alike";
        }

    // Flown whole it would not fit: one line, exit 2, before the DEM is read. On a machine that
    // could hold it, a memory limit below it stands in for this one (never a 26 GB run here).
    std::vector<std::string> env;
    if (machine_memory_bytes() == 0 || machine_memory_bytes() >= whole_bytes)
        env.push_back("TERRASHADE_MEMORY_LIMIT=" + std::to_string(std::int64_t(whole_bytes / 2)));
    const Measured off = run_measured({"fly", dem.string(), "--stream", "off", "--memory-budget", "1024", "--frames",
                                       "3", "--size", "480x270", "--out", (dir_ / "whole").string()},
                                      dir_, 15, env);
    std::printf("fly --stream off: exit %d in %.2f s, peak RSS %.0f MB: %s", off.exit_code, off.seconds,
                off.peak_rss_bytes / 1e6, off.err.c_str());
    ASSERT_FALSE(off.timed_out) << "--stream off went on shading the whole DEM";
    EXPECT_EQ(off.exit_code, 2) << off.out << off.err;
    EXPECT_EQ(count_lines(off.err), 1) << off.err;
    EXPECT_NE(off.err.find("flown whole needs about"), std::string::npos) << off.err;
    EXPECT_NE(off.err.find("--stream"), std::string::npos) << off.err;
    EXPECT_LT(off.seconds, 5.0);
    EXPECT_LT(off.peak_rss_bytes, 300e6);
    EXPECT_FALSE(std::filesystem::exists(dir_ / "whole" / "frame_0000.png"));
}

// A small file with partial tiles: GeoTIFF tags as documented, heights the rounded noise.
TEST_F(FlyStreamCli, BenchDemWritesTheSyntheticMosaic) {
    const int n = 300;
    const auto path = dir_ / "small.tif";
    const Measured gen =
        run_measured({"bench", "dem", std::to_string(n), "--out", path.string(), "--tile", "128"}, dir_, 60);
    ASSERT_EQ(gen.exit_code, 0) << gen.err;
    EXPECT_NE(gen.out.find("300x300"), std::string::npos) << gen.out;
    {
        raster::TiffFile file(path, "r");
        TIFF* tif = file.get();
        EXPECT_TRUE(TIFFIsTiled(tif));
        std::uint32_t tw = 0, th = 0;
        std::uint16_t bits = 0, format = 0, compression = 0, predictor = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        TIFFGetField(tif, TIFFTAG_BITSPERSAMPLE, &bits);
        TIFFGetField(tif, TIFFTAG_SAMPLEFORMAT, &format);
        TIFFGetField(tif, TIFFTAG_COMPRESSION, &compression);
        TIFFGetField(tif, TIFFTAG_PREDICTOR, &predictor);
        EXPECT_EQ(tw, 128u);
        EXPECT_EQ(th, 128u);
        EXPECT_EQ(bits, 16);
        EXPECT_EQ(format, SAMPLEFORMAT_INT);
        EXPECT_EQ(compression, COMPRESSION_ADOBE_DEFLATE);
        EXPECT_EQ(predictor, PREDICTOR_HORIZONTAL);
        char* nodata = nullptr;
        ASSERT_TRUE(TIFFGetField(tif, TIFFTAG_GDAL_NODATA, &nodata));
        EXPECT_STREQ(nodata, "-32768");
    }
    const dem::Dem d = dem::read_dem(path);
    ASSERT_EQ(d.width, n);
    ASSERT_EQ(d.height, n);
    EXPECT_EQ(d.georef.crs().epsg().value_or(0), 4326);
    // The north-west texel centred on 41 N 40 E, 1 arc-second cells.
    const auto nw = d.georef.pixel_to_lonlat(0.5, 0.5);
    EXPECT_NEAR(nw.x, 40.0, 1e-9);
    EXPECT_NEAR(nw.y, 41.0, 1e-9);
    EXPECT_NEAR(d.georef.transform().dx_col, 1.0 / 3600.0, 1e-15);
    EXPECT_EQ(d.void_count(), 0u);
    std::vector<float> expected(std::size_t(n) * std::size_t(n));
    app::synthetic_rows(n, 0, n, expected);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) ASSERT_EQ(d.at(c, r), std::round(expected[d.index(c, r)])) << c << "," << r;
    // The same heights as the mosaic `bench tiles synthetic:N` builds in memory.
    const dem::Dem mosaic = app::synthetic_mosaic(n, 1);
    EXPECT_EQ(mosaic.z, expected);
}

TEST_F(FlyStreamCli, BenchDemBadFlagsAreOneLineAndExitTwo) {
    const auto out = (dir_ / "x.tif").string();
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{"bench", "dem", "1", "--out", out},
                                               {"bench", "dem", "200001", "--out", out},
                                               {"bench", "dem", "300"},
                                               {"bench", "dem", "--out", out},
                                               {"bench", "dem", "300", "--out", out, "--tile", "100"}}) {
        const Measured r = run_measured(args, dir_, 30);
        EXPECT_EQ(r.exit_code, 2) << args[2] << ": " << r.err;
        EXPECT_EQ(count_lines(r.err), 1) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
    EXPECT_NE(run_measured({"bench", "dem", "300"}, dir_, 30).err.find("--out"), std::string::npos);
    EXPECT_NE(run_measured({"bench", "dem", "1", "--out", out}, dir_, 30).err.find("2..200000"), std::string::npos);
}

}  // namespace
}  // namespace ts::cli_test
