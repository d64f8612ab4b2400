// SIGINT and SIGTERM at any moment leave no temporary file, only complete outputs, one line
// saying what was finished, and exit 130 / 143 (app/interrupt_watcher.hpp).
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
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"

extern char** environ;

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;

const std::string kDem = std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif";

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

// Starts terrashade with `args`, sends `sig` `delay` after its signal watcher is up (however
// long a loaded machine takes to get there), waits. The child gets default
// dispositions and an empty mask (a test runner started in the background ignores SIGINT).
Interrupted run_and_signal(const std::vector<std::string>& args, int sig, std::chrono::milliseconds delay,
                           const fs::path& err_path) {
    std::vector<std::string> argv_s = {terrashade()};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&files, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults, empty;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
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
    std::this_thread::sleep_for(delay);
    ::kill(pid, sig);
    ::waitpid(pid, &r.status, 0);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attr);
    std::ifstream in(err_path);
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return r;
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
        const Interrupted r = run_and_signal(args, sig, delay, root / ("err" + std::to_string(attempt)));
        ASSERT_TRUE(WIFEXITED(r.status)) << "attempt " << attempt << ": killed by signal " << WTERMSIG(r.status);
        const int code = WEXITSTATUS(r.status);
        int frames = 0;
        if (fs::exists(out))
            for (const auto& e : fs::directory_iterator(out)) {
                const std::string name = e.path().filename().string();
                EXPECT_FALSE(name.starts_with(".")) << "attempt " << attempt << ": temporary file left: " << name;
                if (name == "times.csv") continue;  // written whole after the last frame
                EXPECT_TRUE(complete_png(e.path())) << "attempt " << attempt << ": incomplete " << name;
                ++frames;
            }
        if (code == 0) continue;  // finished before the signal
        ++interrupted;
        EXPECT_EQ(code, 128 + sig) << "attempt " << attempt << ": " << r.err;
        const std::string line = "terrashade: interrupted; " + std::to_string(frames) + " of 145 frames written\n";
        EXPECT_TRUE(r.err.ends_with(line)) << "attempt " << attempt << ": " << r.err;
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

}  // namespace
}  // namespace ts::cli_test
