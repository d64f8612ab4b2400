#pragma once
// The names in a directory read with getdents64 into a buffer on the stack: no allocation, so
// it works while other threads are stopped holding the allocator's lock (the interrupt path,
// core/util/temp_files.hpp, app/interrupt_watcher.hpp). Linux only.
#include <cstdint>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace ts {

// Calls f(name) for every entry of the open directory `dir_fd` but "." and "..".
template <class F>
void for_each_directory_entry(int dir_fd, F&& f) {
    struct Entry {  // struct linux_dirent64
        std::uint64_t ino;
        std::int64_t off;
        unsigned short reclen;
        unsigned char type;
        char name[1];
    };
    alignas(8) char buf[8192];
    for (;;) {
        const long n = ::syscall(SYS_getdents64, dir_fd, buf, sizeof buf);
        if (n <= 0) return;
        for (long off = 0; off < n;) {
            const auto* e = reinterpret_cast<const Entry*>(buf + off);
            const char* name = e->name;
            const bool dots = name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'));
            if (!dots) f(name);
            off += e->reclen;
        }
    }
}

}  // namespace ts
