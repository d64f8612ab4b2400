#include "core/util/temp_files.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <random>
#include <string>
#include <system_error>
#include <vector>
#include <fcntl.h>
#include <unistd.h>

#include "core/util/directory_entries.hpp"
#include "core/util/error.hpp"

namespace ts::temp_files {
namespace fs = std::filesystem;

namespace {

struct Registry {
    std::mutex mutex;
    std::vector<fs::path> tracked;
    std::vector<fs::path> directories;
    std::vector<std::pair<fs::path, std::string>> created;  // (folder, its own file)
    std::atomic<std::uint64_t> committed{0};
};

// Never destroyed: the interrupt watcher may use it while static destructors run at exit.
Registry& registry() {
    static Registry* r = new Registry;
    return *r;
}

void forget_locked(Registry& r, const fs::path& tmp) {
    const auto it = std::find(r.tracked.begin(), r.tracked.end(), tmp);
    if (it != r.tracked.end()) r.tracked.erase(it);
}

}  // namespace

fs::path sibling_for(const fs::path& target) {
    static std::atomic<unsigned> sequence{0};
    std::random_device rd;
    // The sequence number keeps two temps of one process apart even if the random tags collide.
    const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000) +
                            std::to_string(sequence.fetch_add(1) % 10);
    fs::path tmp = target;
    tmp.replace_filename("." + target.stem().string() + ".tmp-" + tag + target.extension().string());
    return tmp;
}

void track(const fs::path& tmp) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.tracked.push_back(tmp);
}

void forget(const fs::path& tmp) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    forget_locked(r, tmp);
}

void track_directory(const fs::path& dir) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.directories.push_back(dir);
}

void forget_directory(const fs::path& dir) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    const auto it = std::find(r.directories.begin(), r.directories.end(), dir);
    if (it != r.directories.end()) r.directories.erase(it);
}

void track_created_directory(const fs::path& dir, const std::string& own_file) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.created.emplace_back(dir, own_file);
}

void commit(std::span<const std::pair<fs::path, fs::path>> moves) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    for (std::size_t i = 0; i < moves.size(); ++i) {
        std::error_code ec;
        fs::rename(moves[i].first, moves[i].second, ec);
        if (ec) {
            for (std::size_t k = i; k < moves.size(); ++k) {
                std::error_code ignored;
                fs::remove(moves[k].first, ignored);
                forget_locked(r, moves[k].first);
            }
            throw input_error(moves[i].second.string(), "cannot write: " + ec.message());
        }
        forget_locked(r, moves[i].first);
        r.committed.fetch_add(1);
    }
}

std::uint64_t committed_count() { return registry().committed.load(); }

void hold_for_exit() {
    registry().mutex.lock();  // never unlocked: the process is about to end
}

std::size_t remove_held() {
    std::size_t removed = 0;
    for (const fs::path& p : registry().tracked)
        if (::unlink(p.c_str()) == 0) ++removed;
    for (const fs::path& dir : registry().directories) {
        const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd < 0) continue;
        // Unlinking while reading may skip entries: read again until nothing is left.
        for (int pass = 0; pass < 8; ++pass) {
            bool any = false;
            ::lseek(fd, 0, SEEK_SET);
            for_each_directory_entry(fd, [&](const char* name) {
                if (::unlinkat(fd, name, 0) == 0) ++removed, any = true;
            });
            if (!any) break;
        }
        ::close(fd);
        ::rmdir(dir.c_str());
    }
    // Created output folders with nothing of value in them (after their temporaries went above).
    for (const auto& entry : registry().created) {
        // Named apart, not a structured binding: clang 14 (the fuzz build) cannot capture one.
        const auto& dir = entry.first;
        const auto& own = entry.second;
        const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd < 0) continue;
        bool others = false;
        for_each_directory_entry(fd, [&](const char* name) { others = others || own.empty() || own != name; });
        if (!others && !own.empty()) ::unlinkat(fd, own.c_str(), 0);
        ::close(fd);
        ::rmdir(dir.c_str());  // fails, as it should, if anything is left
    }
    return removed;
}

}  // namespace ts::temp_files
