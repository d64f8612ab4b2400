#include "app/interrupt_watcher.hpp"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <pthread.h>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>
#include <fcntl.h>

#include "core/util/directory_entries.hpp"
#include "core/util/temp_files.hpp"

namespace ts::app::interrupt {
namespace {

// What the summary line reports (set by report_progress, read by the watcher).
std::atomic<const char*> g_unit{nullptr};
std::atomic<std::uint64_t> g_total{0};
std::atomic<std::uint64_t> g_committed_before{0};
// What an interrupt keeps on purpose (report_kept): written before it is published.
char g_kept_text[1024];
std::atomic<bool> g_kept{false};

// Threads that reached the freeze handler.
std::atomic<int> g_frozen{0};

int freeze_signal() { return SIGRTMIN + 2; }

void freeze_handler(int) {
    g_frozen.fetch_add(1);
    for (;;) ::pause();
}

// The process's threads, from /proc/self/task (allocation-free). Calls f(tid) for each.
template <class F>
void for_each_thread(F&& f) {
    const int fd = ::open("/proc/self/task", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    for_each_directory_entry(fd, [&](const char* name) { f(int(std::strtol(name, nullptr, 10))); });
    ::close(fd);
}

void sleep_ms(long ms) {
    timespec t{0, ms * 1000000L};
    ::nanosleep(&t, nullptr);
}

// Stops every thread but this one inside freeze_handler, so none creates, writes or renames a
// file any more. Threads started meanwhile are found by the next pass; a thread that ends
// before it is counted costs at most the wait's deadline.
void freeze_other_threads() {
    constexpr int kMaxThreads = 4096;
    static int signalled[kMaxThreads];
    int count = 0;
    const int self = int(::syscall(SYS_gettid));
    const int pid = ::getpid();
    for (int pass = 0; pass < 16; ++pass) {
        int fresh = 0;
        for_each_thread([&](int tid) {
            if (tid == self || count >= kMaxThreads) return;
            for (int i = 0; i < count; ++i)
                if (signalled[i] == tid) return;
            if (::syscall(SYS_tgkill, pid, tid, freeze_signal()) == 0) {
                signalled[count++] = tid;
                ++fresh;
            }
        });
        if (fresh == 0) return;
        for (int waited = 0; g_frozen.load() < count && waited < 2000; ++waited) sleep_ms(1);
    }
}

void write_all(int fd, const char* s, std::size_t n) {
    while (n > 0) {
        const ssize_t w = ::write(fd, s, n);
        if (w <= 0) return;
        s += w, n -= std::size_t(w);
    }
}

// stdout may hold lines not yet written (a pipe is fully buffered); flush it unless a stopped
// thread holds its lock.
void flush_stdout() {
    if (::ftrylockfile(stdout) == 0) {
        std::fflush(stdout);
        ::funlockfile(stdout);
    }
}

void print_summary() {
    const std::uint64_t committed = temp_files::committed_count() - g_committed_before.load();
    char line[1400];
    const char* unit = g_unit.load();
    // A progress bar may own the current line of a terminal.
    const char* lead = ::isatty(STDERR_FILENO) ? "\n" : "";
    if (unit) {
        const std::uint64_t total = g_total.load();
        std::snprintf(line, sizeof line, "%sterrashade: interrupted; %llu of %llu %s written\n", lead,
                      static_cast<unsigned long long>(committed < total ? committed : total),
                      static_cast<unsigned long long>(total), unit);
    } else if (committed == 0) {
        std::snprintf(line, sizeof line, "%sterrashade: interrupted; no output was written or changed\n", lead);
    } else {
        std::snprintf(line, sizeof line, "%sterrashade: interrupted; %llu file%s written\n", lead,
                      static_cast<unsigned long long>(committed), committed == 1 ? "" : "s");
    }
    std::size_t n = std::strlen(line);
    if (g_kept.load() && n > 0) {
        std::snprintf(line + n - 1, sizeof line - (n - 1), "; %s\n", g_kept_text);
        n = std::strlen(line);
    }
    write_all(STDERR_FILENO, line, n);
}

}  // namespace

struct InterruptIndex::Item {
    std::string file, line;
    std::atomic<bool> ready{false};
};

namespace {
std::atomic<InterruptIndex*> g_index{nullptr};
}  // namespace

InterruptIndex& index_on_interrupt(const std::string& path, const std::string& header, std::size_t items) {
    static InterruptIndex* index = new InterruptIndex;  // never freed: the watcher may read it at exit
    g_index.store(nullptr);
    delete[] index->items_;
    index->path_ = path, index->tmp_ = path + ".interrupted-tmp", index->header_ = header;
    index->items_ = new InterruptIndex::Item[items];
    index->count_ = items;
    g_index.store(index);
    return *index;
}

void InterruptIndex::set(std::size_t k, const std::string& file, const std::string& line) {
    if (k >= count_) return;
    items_[k].file = file, items_[k].line = line;
    items_[k].ready.store(true, std::memory_order_release);
}

void InterruptIndex::forget() { g_index.store(nullptr); }

void write_index() {
    const InterruptIndex* x = g_index.load();
    if (!x) return;
    bool any = false;
    for (std::size_t k = 0; k < x->count_ && !any; ++k)
        any = x->items_[k].ready.load(std::memory_order_acquire) && ::access(x->items_[k].file.c_str(), F_OK) == 0;
    if (!any) return;
    const int fd = ::open(x->tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return;
    write_all(fd, x->header_.data(), x->header_.size());
    for (std::size_t k = 0; k < x->count_; ++k) {
        const InterruptIndex::Item& it = x->items_[k];
        if (it.ready.load(std::memory_order_acquire) && ::access(it.file.c_str(), F_OK) == 0)
            write_all(fd, it.line.data(), it.line.size());
    }
    const bool ok = ::fsync(fd) == 0;
    ::close(fd);
    if (ok) ::rename(x->tmp_.c_str(), x->path_.c_str());
    else ::unlink(x->tmp_.c_str());
}

namespace {

void watch(sigset_t set) {
    int sig = 0;
    while (::sigwait(&set, &sig) != 0) {
    }
    temp_files::hold_for_exit();
    freeze_other_threads();
    write_index();  // before remove_held: an index that lists frames keeps their created folder
    temp_files::remove_held();
    flush_stdout();
    print_summary();
    ::_exit(128 + sig);
}

bool ignored_at_start(int sig) {
    struct sigaction current {};
    return ::sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN;
}

}  // namespace

void start() {
    struct sigaction freeze {};
    freeze.sa_handler = freeze_handler;
    sigfillset(&freeze.sa_mask);  // nothing interrupts a thread on its way into pause()
    ::sigaction(freeze_signal(), &freeze, nullptr);

    sigset_t set;
    sigemptyset(&set);
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
        if (!ignored_at_start(sig)) sigaddset(&set, sig);
    if (sigisemptyset(&set)) return;
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(watch, set).detach();
}

void report_kept(const std::string& kept) {
    g_kept.store(false);
    std::snprintf(g_kept_text, sizeof g_kept_text, "%s", kept.c_str());
    g_kept.store(true);
}

void report_progress(const char* unit, std::uint64_t total) {
    g_committed_before.store(temp_files::committed_count());
    g_total.store(total);
    g_unit.store(unit);
}

}  // namespace ts::app::interrupt
