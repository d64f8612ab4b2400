#include "app/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <functional>
#include <system_error>

#include "core/util/error.hpp"
#include "core/util/temp_files.hpp"

namespace ts::app {
namespace fs = std::filesystem;

namespace {

// The output as one spelling: absolute, symlinks of its existing part resolved, ".." gone.
std::string normalised(const fs::path& p) {
    std::error_code ec;
    const fs::path a = fs::absolute(p, ec);
    fs::path c = fs::weakly_canonical(a, ec);
    if (ec) c = a.lexically_normal();
    std::string s = c.string();
    while (s.size() > 1 && s.back() == '/') s.pop_back();  // "out/" and "out" are one folder
    return s;
}

fs::path lock_folder() {
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    return ec ? fs::path("/tmp") : base;
}

}  // namespace

OutputLock::OutputLock(const fs::path& output, const std::string& what) {
    const std::string key = normalised(output);
    char name[64];
    std::snprintf(name, sizeof name, "terrashade-%u-%016zx.lock", unsigned(::getuid()), std::hash<std::string>{}(key));
    file_ = lock_folder() / name;
    temp_files::track(file_);  // an interrupt removes it with the temporaries
    for (;;) {
        fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
        if (fd_ < 0) {  // a read-only temporary folder: run unguarded rather than not at all
            temp_files::forget(file_);
            return;
        }
        if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) break;
        // The holder before us removes the file as it lets go: a lock on a file no longer at
        // the path guards nothing, so take the one there now.
        struct stat held {}, named {};
        if (::fstat(fd_, &held) == 0 && ::stat(file_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
            held.st_dev == named.st_dev) {
            const std::string text = std::to_string(::getpid()) + "\n" + key + "\n";
            if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, text.data(), text.size(), 0) < 0) {
                // The process id is only for the message of a refused job.
            }
            return;
        }
        ::close(fd_);
    }
    // Held by another job: its process id, written when it took the lock, names it.
    char pid[32] = "";
    const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
    pid[n > 0 ? n : 0] = '\0';
    for (char* c = pid; *c; ++c)
        if (*c == '\n') *c = '\0';
    ::close(fd_);
    fd_ = -1;
    temp_files::forget(file_);  // the other job's
    const std::string who = *pid ? " (process " + std::string(pid) + ")" : "";
    throw input_error(output.string(),
                      "another terrashade job" + who + " is writing it; wait for it to end, or write elsewhere (" + what + ")");
}

OutputLock::~OutputLock() {
    if (fd_ < 0) return;
    ::unlink(file_.c_str());  // nothing left behind; a job waiting on it retries (above)
    temp_files::forget(file_);
    ::close(fd_);  // closing drops the flock
}

}  // namespace ts::app
