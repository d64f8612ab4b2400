#include "core/util/isolated_call.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <exception>
#include <new>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/util/error.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define TS_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TS_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef TS_ADDRESS_SANITIZER
#define TS_ADDRESS_SANITIZER 0
#endif

namespace ts {
namespace {

// What the child writes first: how its work ended.
enum class Outcome : std::uint8_t { done = 0, failed = 1, out_of_memory = 2 };

bool write_all(int fd, const void* data, std::size_t n) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (n > 0) {
        const ssize_t k = ::write(fd, p, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        p += k;
        n -= std::size_t(k);
    }
    return true;
}

// Ends the child at once: no destructors or atexit handlers of the parent's objects, and no
// sanitizer exit hooks (a leak check of the parent's whole heap took over a second per child).
[[noreturn]] void leave(int code) {
    syscall(SYS_exit_group, code);
    _exit(code);
}

[[noreturn]] void child_main(int fd, const std::function<std::vector<std::uint8_t>()>& work,
                             const IsolationLimits& limits) {
    // Dies with the parent (a parent killed while waiting leaves no orphan importer behind).
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() == 1) leave(3);
#if !TS_ADDRESS_SANITIZER
    if (limits.extra_address_space_bytes > 0) {
        // What is mapped already (the caller's heap, stacks, libraries) plus the allowance.
        unsigned long long pages = 0;
        if (FILE* f = std::fopen("/proc/self/statm", "r")) {
            if (std::fscanf(f, "%llu", &pages) != 1) pages = 0;
            std::fclose(f);
        }
        const std::uint64_t mapped = std::uint64_t(pages) * std::uint64_t(sysconf(_SC_PAGESIZE));
        const rlim_t cap = rlim_t(mapped + limits.extra_address_space_bytes);
        const rlimit r{cap, cap};
        setrlimit(RLIMIT_AS, &r);
    }
#else
    (void)limits;
#endif
    Outcome outcome = Outcome::done;
    std::vector<std::uint8_t> payload;
    try {
        payload = work();
    } catch (const std::bad_alloc&) {
        outcome = Outcome::out_of_memory;
        payload.clear();
    } catch (const std::exception& e) {
        outcome = Outcome::failed;
        const std::string m = e.what();
        payload.assign(m.begin(), m.end());
    } catch (...) {
        outcome = Outcome::failed;
        payload.clear();
    }
    const bool ok = write_all(fd, &outcome, 1) && write_all(fd, payload.data(), payload.size());
    leave(ok ? 0 : 4);
}

}  // namespace

std::vector<std::uint8_t> run_isolated(const std::function<std::vector<std::uint8_t>()>& work, const std::string& what,
                                       const IsolationLimits& limits) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw input_error(what, std::string("cannot start a child process: ") + std::strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) {
        const int err = errno;
        close(fds[0]);
        close(fds[1]);
        throw input_error(what, std::string("cannot start a child process: ") + std::strerror(err));
    }
    if (pid == 0) {
        close(fds[0]);
        child_main(fds[1], work, limits);
    }
    close(fds[1]);

    // Read until the child closes its end, at most until the deadline.
    std::vector<std::uint8_t> bytes;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.timeout_s);
    bool timed_out = false;
    std::uint8_t buf[1 << 16];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) break;
        if (r == 0) continue;
        const ssize_t k = read(fds[0], buf, sizeof buf);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) break;
        bytes.insert(bytes.end(), buf, buf + k);
    }
    close(fds[0]);
    if (timed_out) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timed_out)
        throw input_error(what, "reading it did not finish within " + std::to_string(int(limits.timeout_s)) +
                                    " s (a malformed file?)");
    if (WIFSIGNALED(status))
        throw input_error(what, std::string("the reader crashed on it (") + strsignal(WTERMSIG(status)) +
                                    "; a malformed or unsupported file?)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
        throw input_error(what, "the reader stopped without a result (a malformed file?)");
    const auto outcome = Outcome(bytes[0]);
    bytes.erase(bytes.begin());
    if (outcome == Outcome::out_of_memory) throw input_error(what, "reading it needs more memory than is available");
    if (outcome == Outcome::failed) {
        std::string message(bytes.begin(), bytes.end());
        if (message.empty()) message = what + ": could not be read";
        throw InputError(message);
    }
    if (outcome != Outcome::done) throw input_error(what, "the reader returned a malformed result");
    return bytes;
}

}  // namespace ts
