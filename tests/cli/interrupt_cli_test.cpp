// SIGINT, SIGTERM and SIGHUP at any moment leave no temporary file, only complete outputs (and
// what --resume needs, said so), one line saying what was finished, and exit 130 / 143 / 129
// (app/interrupt_watcher.hpp).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "tests/cli/reliability_support.hpp"

extern char** environ;

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;

struct Interrupted {
    int status = 0;
    std::string err;
};

// Whether process `pid` blocks SIGINT and SIGTERM, as terrashade's main() does first
// (app/interrupt_watcher.hpp): from then on a signal is its to handle. Before, the loader and
// static initialisers are still running and the default disposition would end it.
bool watches_signals(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.starts_with("SigBlk:")) {
            const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
            const unsigned long long both = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1));
            return (mask & both) == both;
        }
    return false;
}

// Starts terrashade with `args`, sends `sig` once its signal watcher is up (however long a
// loaded machine takes to get there) and `ready()` holds (a deterministic point: a file
// appeared, a line was printed), then `delay` later, and waits. No signal if the process ends
// first. The child gets default dispositions and an empty mask (a test runner started in the
// background ignores SIGINT); its stdout goes to `out_path` (default /dev/null).
Interrupted run_and_signal(const std::vector<std::string>& args, int sig, std::chrono::milliseconds delay,
                           const fs::path& err_path, const std::function<bool()>& ready = {},
                           const fs::path& out_path = "/dev/null") {
    std::vector<std::string> argv_s = {terrashade()};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&files, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults, empty;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    sigaddset(&defaults, SIGHUP);
    sigemptyset(&empty);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setsigmask(&attr, &empty);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    pid_t pid = 0;
    Interrupted r;
    if (posix_spawn(&pid, argv[0], &files, &attr, argv.data(), environ) != 0) return r;
    const auto start = std::chrono::steady_clock::now();
    while (!watches_signals(pid) && std::chrono::steady_clock::now() - start < std::chrono::seconds(30))
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    bool ended = false;
    while (ready && !ready() && !ended) {
        ended = ::waitpid(pid, &r.status, WNOHANG) == pid;
        if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (!ended) {
        std::this_thread::sleep_for(delay);
        ::kill(pid, sig);
        ::waitpid(pid, &r.status, 0);
    }
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attr);
    std::ifstream in(err_path);
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return r;
}

// Files and folders under `dir` an interrupt must not leave: temporaries (hidden, ".tmp-"),
// SQLite's -shm, empty folders, folders holding only a tile job file.
std::vector<std::string> leftovers(const fs::path& dir) {
    std::vector<std::string> bad;
    if (!fs::exists(dir)) return bad;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.find(".tmp-") != std::string::npos || name.ends_with("-shm")) bad.push_back(e.path().string());
        if (e.is_directory()) {
            std::vector<std::string> inside;
            for (const auto& f : fs::directory_iterator(e.path())) inside.push_back(f.path().filename().string());
            if (inside.empty() || (inside.size() == 1 && inside[0] == ".terrashade-tiles.json"))
                bad.push_back(e.path().string() + "/ (nothing of value in it)");
        }
    }
    return bad;
}

// A PNG is complete when it ends with its IEND chunk.
bool complete_png(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    static const std::string iend("IEND\xae\x42\x60\x82", 8);
    return bytes.size() > 57 && bytes.compare(0, 4, "\x89PNG") == 0 &&
           bytes.compare(bytes.size() - iend.size(), iend.size(), iend) == 0;
}

TEST(InterruptCli, RelightLeavesCompleteFramesOnlyAndSaysHowMany) {
    const fs::path root = temp_dir("interrupt_relight");
    // 145 frames of 600x600 (resampled from a 101x101 crop): each frame is cheap to shade and
    // slow enough to encode that a signal often lands while a PNG is being written.
    const std::vector<std::string> base = {kDem, "--crop", "5.65,45.10,5.85,45.30", "--size", "600x600",
                                           "--directions", "8", "--times",
                                           "2025-06-21T06:00:00Z/2025-06-21T18:00:00Z/PT5M"};
    int interrupted = 0;
    for (int attempt = 0; attempt < 12; ++attempt) {
        const int sig = attempt % 2 ? SIGTERM : SIGINT;
        const fs::path out = root / ("run" + std::to_string(attempt));
        fs::remove_all(out);  // a repeated test starts afresh
        std::vector<std::string> args = {"relight"};
        args.insert(args.end(), base.begin(), base.end());
        args.insert(args.end(), {"--out", out.string()});
        const auto delay = std::chrono::milliseconds(100 + 75 * attempt);
        // The delay counts from the output folder's creation, just before the frames begin: a
        // signal that lands earlier (reading the DEM on a loaded machine) ends the job before
        // it has frames to count, with its own line (checked below).
        const Interrupted r = run_and_signal(args, sig, delay, root / ("err" + std::to_string(attempt)),
                                             [&] { return fs::exists(out); });
        ASSERT_TRUE(WIFEXITED(r.status)) << "attempt " << attempt << ": killed by signal " << WTERMSIG(r.status);
        const int code = WEXITSTATUS(r.status);
        int frames = 0;
        std::vector<std::string> frame_files;
        if (fs::exists(out))
            for (const auto& e : fs::directory_iterator(out)) {
                const std::string name = e.path().filename().string();
                EXPECT_FALSE(name.starts_with(".")) << "attempt " << attempt << ": temporary file left: " << name;
                if (name == "times.csv") continue;
                EXPECT_TRUE(complete_png(e.path())) << "attempt " << attempt << ": incomplete " << name;
                frame_files.push_back(name);
                ++frames;
            }
        // times.csv lists exactly the frames on disk; none, and no folder, if there are none.
        std::sort(frame_files.begin(), frame_files.end());
        if (frames > 0) {
            EXPECT_EQ(csv_files(out / "times.csv"), frame_files) << "attempt " << attempt;
        } else {
            EXPECT_FALSE(fs::exists(out)) << "attempt " << attempt << ": an empty folder was left";
        }
        if (code == 0) continue;  // finished before the signal
        ++interrupted;
        EXPECT_EQ(code, 128 + sig) << "attempt " << attempt << ": " << r.err;
        const std::string line = "terrashade: interrupted; " + std::to_string(frames) + " of 145 frames written\n";
        const bool before_frames =
            frames == 0 && r.err.ends_with("terrashade: interrupted; no output was written or changed\n");
        EXPECT_TRUE(r.err.ends_with(line) || before_frames) << "attempt " << attempt << ": " << r.err;
    }
    EXPECT_GE(interrupted, 10);
}

TEST(InterruptCli, RenderInterruptedDuringTheVisibilityChangesNothing) {
    const fs::path dir = temp_dir("interrupt_render");
    const fs::path png = dir / "ex.png";
    std::ofstream(png) << "the previous picture";
    const Interrupted r = run_and_signal({"render", kDem, "--directions", "1024", "--sun-azimuth", "135",
                                          "--sun-elevation", "30", "--out", png.string()},
                                         SIGINT, std::chrono::milliseconds(700), dir / "err");
    ASSERT_TRUE(WIFEXITED(r.status));
    EXPECT_EQ(WEXITSTATUS(r.status), 130) << r.err;
    EXPECT_TRUE(r.err.ends_with("terrashade: interrupted; no output was written or changed\n")) << r.err;
    std::ifstream in(png);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(content, "the previous picture");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);  // ex.png, err
}


const char* signal_name(int sig) { return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "SIGHUP"; }

// Every long command under each signal, sent once it runs (its watcher up, its first line or
// file out where it has one): it ends with 128 + the signal and one "interrupted" line, or
// finished first (exit 0); either way no temporary, no -shm, no empty or job-only folder.
TEST(InterruptCli, EveryLongCommandEndsCleanlyOnEverySignal) {
    const fs::path root = temp_dir("interrupt_every");
    const std::string truck = std::string(TS_SHARED_DATA) + "/meshes/CesiumMilkTruck/CesiumMilkTruck.gltf";
    const fs::path path_csv = root / "path.csv";
    std::ofstream(path_csv) << "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n"
                               "0,5.55,45.08,2500,45,-5,0\n12,5.70,45.18,2200,60,-8,0\n";
    // Two shards to merge, made once.
    const fs::path shards = root / "shards";
    for (const char* k : {"0", "1"}) {
        const std::string cmd = quote(terrashade()) + " tiles " + quote(kDem) + " --zoom 8-11 --style hillshade --shard " +
                                k + "/2 --out " + quote((shards / k).string()) + " > /dev/null 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0);
    }
    struct Case {
        std::string name;
        std::vector<std::string> args;  // "OUT" is replaced by the run's output folder
        std::string ready = "";         // signalled once OUT/ready exists (empty: once the watcher is up)
    };
    const std::string sun_az = "--sun-azimuth", sun_el = "--sun-elevation";
    std::vector<Case> cases = {
        {"render", {"render", kDem, "--directions", "1024", sun_az, "135", sun_el, "30", "--out", "OUT/x.png"}},
        {"relight", {"relight", kDem, "--directions", "64", "--times", "2025-06-21T06:00Z/2025-06-21T18:00Z/PT30M",
                     "--out", "OUT/frames"}, "frames"},
        {"tiles-xyz", {"tiles", kDem, "--zoom", "8-14", "--style", "relief", "--directions", "64", "--out", "OUT/t"},
         "t/.terrashade-tiles.json"},
        {"tiles-mbtiles",
         {"tiles", kDem, "--zoom", "8-14", "--style", "relief", "--directions", "64", "--out", "OUT/t.mbtiles"},
         "t.mbtiles.partial"},
        {"visibility", {"visibility", kDem, "--directions", "4096", "--svf", "OUT/svf.tif"}},
        {"hillshade", {"hillshade", kDem, "--out", "OUT/h.tif"}},
        {"merge", {"merge", (shards / "0").string(), (shards / "1").string(), "--out", "OUT/merged"}},
        {"fly", {"fly", kDem, "--frames", "40", "--size", "320x180", "--directions", "8", "--path", path_csv.string(),
                 "--out", "OUT/fly"}, "fly"},
    };
    if (fs::exists(truck))
        cases.push_back({"spheres", {"spheres", truck, "--count", "512", "--no-cache", "--out", "OUT/s.json"}});
    int interrupted = 0, runs = 0;
    for (const Case& c : cases)
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
            const fs::path out = root / (c.name + "_" + signal_name(sig));
            fs::remove_all(out);
            fs::create_directories(out);
            std::vector<std::string> args = c.args;
            for (std::string& a : args)
                if (a.starts_with("OUT")) a = out.string() + a.substr(3);
            const Interrupted r = run_and_signal(args, sig, std::chrono::milliseconds(0),
                                                 root / (c.name + "_" + signal_name(sig) + ".err"),
                                                 [&] { return c.ready.empty() || fs::exists(out / c.ready); });
            ++runs;
            const std::string what = c.name + " " + signal_name(sig) + ": " + r.err;
            ASSERT_TRUE(WIFEXITED(r.status)) << what << " killed by signal " << WTERMSIG(r.status);
            const int code = WEXITSTATUS(r.status);
            EXPECT_TRUE(code == 0 || code == 128 + sig) << what << " exit " << code;
            if (code == 128 + sig) {
                ++interrupted;
                const auto last = r.err.rfind("terrashade: interrupted; ");
                EXPECT_NE(last, std::string::npos) << what;
                if (last != std::string::npos) {
                    EXPECT_EQ(r.err.find('\n', last), r.err.size() - 1) << what;
                }
            }
            EXPECT_EQ(leftovers(out), std::vector<std::string>{}) << what;
        }
    // Most runs are long enough to be caught; a test whose signals all came too late proves nothing.
    EXPECT_GE(interrupted, runs / 2);
}

// Ctrl-C in an MBTiles export keeps FILE.partial and its -wal (the committed tiles) and says so;
// --resume then finishes the file and nothing else remains.
TEST(InterruptCli, MbtilesKeepsExactlyWhatResumeNeeds) {
    const fs::path dir = temp_dir("interrupt_mbtiles");
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        const fs::path t = dir / (std::string(signal_name(sig)) + ".mbtiles");
        const std::string partial = t.string() + ".partial";
        // 1106 tiles, about 5 s on one thread.
        std::vector<std::string> args = {"tiles", kDem, "--zoom", "8-13", "--style", "hillshade", "--threads", "1",
                                         "--out", t.string()};
        // Once a batch of tiles is committed (read through SQLite, as a resumed run reads it).
        const Interrupted r = run_and_signal(args, sig, std::chrono::milliseconds(0), dir / "err",
                                             [&] { return committed_tiles(partial) >= 64; });
        ASSERT_TRUE(WIFEXITED(r.status));
        ASSERT_EQ(WEXITSTATUS(r.status), 128 + sig) << "finished before the signal: give it more tiles\n" << r.err;
        EXPECT_NE(r.err.find("kept in " + partial), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(t));
        EXPECT_TRUE(fs::exists(partial));
        EXPECT_FALSE(fs::exists(partial + "-shm"));
        EXPECT_EQ(leftovers(dir), std::vector<std::string>{});
        args.push_back("--resume");
        std::string cmd = quote(terrashade());
        for (const std::string& a : args) cmd += " " + quote(a);
        const fs::path log = dir / "resume.out";
        ASSERT_EQ(std::system((cmd + " > " + quote(log.string()) + " 2>&1").c_str()), 0) << slurp(log);
        const std::string out = slurp(log);
        const auto at = out.find(" written, ");
        ASSERT_NE(at, std::string::npos) << out;
        EXPECT_GE(std::stoul(out.substr(at + 10)), 64u) << "the committed tiles were not resumed: " << out;
        EXPECT_TRUE(fs::exists(t));
        for (const char* suffix : {".partial", ".partial-wal", ".partial-shm"})
            EXPECT_FALSE(fs::exists(t.string() + suffix)) << suffix;
    }
}

// An interrupt before the first output (during the visibility) removes the folder the command
// created: relight's frame folder, the tiles folder with its job file.
TEST(InterruptCli, InterruptBeforeTheFirstOutputLeavesNoFolder) {
    const fs::path dir = temp_dir("interrupt_setup");
    const fs::path frames = dir / "frames";
    // Signalled once the visibility starts (seconds with 1024 directions); the folder appears
    // only after it, when the first frame is about to be written.
    const fs::path said = dir / "out";
    const Interrupted r = run_and_signal({"relight", kDem, "--directions", "1024", "--times",
                                          "2025-06-21T06:00Z/2025-06-21T08:00Z/PT1H", "--out", frames.string()},
                                         SIGHUP, std::chrono::milliseconds(0), dir / "err",
                                         [&] {
                                             std::ifstream in(said);
                                             std::string text((std::istreambuf_iterator<char>(in)),
                                                              std::istreambuf_iterator<char>());
                                             return text.find("visibility") != std::string::npos;
                                         },
                                         said);
    ASSERT_TRUE(WIFEXITED(r.status));
    EXPECT_EQ(WEXITSTATUS(r.status), 129) << r.err;
    EXPECT_NE(r.err.find("terrashade: interrupted; "), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(frames));

    const fs::path tiles = dir / "tiles";
    const Interrupted t = run_and_signal({"tiles", kDem, "--zoom", "13", "--style", "relief", "--directions", "1024",
                                          "--out", tiles.string()},
                                         SIGINT, std::chrono::milliseconds(0), dir / "err2",
                                         [&] { return fs::exists(tiles / ".terrashade-tiles.json"); });
    ASSERT_TRUE(WIFEXITED(t.status));
    EXPECT_EQ(WEXITSTATUS(t.status), 130) << t.err;
    // The folder is gone, unless tiles were already written (then they stay, with their job).
    EXPECT_EQ(leftovers(dir), std::vector<std::string>{});
}

// tiles --overwrite replaces the old set when its first tile is written: interrupted during the
// shading, the old tiles, job and viewer are all still there.
TEST(InterruptCli, AnOverwriteInterruptedDuringTheShadingKeepsTheOldSet) {
    const fs::path dir = temp_dir("interrupt_overwrite");
    const fs::path tiles = dir / "tiles";
    ASSERT_EQ(run(ts_cmd("tiles " + quote(kDem) + " --zoom 9 --style hillshade --out " + quote(tiles.string()))).exit_code, 0);
    std::map<std::string, std::string> before;
    for (const auto& e : fs::recursive_directory_iterator(tiles))
        if (e.is_regular_file()) before[e.path().string()] = slurp(e.path());
    const fs::path said = dir / "out";
    const Interrupted r = run_and_signal({"tiles", kDem, "--zoom", "13", "--style", "relief", "--directions", "1024", "-v",
                                          "--overwrite", "--out", tiles.string()},
                                         SIGINT, std::chrono::milliseconds(0), dir / "err",
                                         [&] { return slurp(said).find("zoom 13:") != std::string::npos; }, said);
    ASSERT_TRUE(WIFEXITED(r.status));
    EXPECT_EQ(WEXITSTATUS(r.status), 130) << r.err;
    std::map<std::string, std::string> after;
    for (const auto& e : fs::recursive_directory_iterator(tiles))
        if (e.is_regular_file()) after[e.path().string()] = slurp(e.path());
    EXPECT_EQ(after, before);
}

}  // namespace
}  // namespace ts::cli_test
