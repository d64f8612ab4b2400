#pragma once
// Runs a piece of work in a child process and hands back the bytes it produced, so that a
// library we cannot fix (a file-format parser fed an arbitrary file) cannot take the calling
// process down with it: a crash, a hang or a runaway allocation in the child becomes one
// ts::InputError in the parent. Used for mesh import (assimp, core/mesh/mesh_import.cpp).
//
// The child is a fork of the caller: it sees the caller's memory as it was, runs `work`, writes
// the result down a pipe and leaves with _exit (no destructors, no atexit handlers of the
// parent run twice). Only the calling thread exists in the child, so `work` must not wait on
// anything another thread of the parent holds; glibc's allocator is safe to use after fork.
// POSIX only.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ts {

struct IsolationLimits {
    // Seconds the child may take before it is killed (its work is then reported as hung).
    double timeout_s = 120.0;
    // Address space the child may map beyond what it inherited from the caller, bytes; 0 = no
    // limit. Not applied in sanitizer builds, whose shadow memory is a reservation of terabytes.
    std::uint64_t extra_address_space_bytes = 0;
};

// Runs work() in a child process and returns what it returned. Throws ts::InputError naming
// `what` (e.g. the file being read) when work() threw (with its message), when the child died
// of a signal, ran out of memory, or exceeded the timeout.
std::vector<std::uint8_t> run_isolated(const std::function<std::vector<std::uint8_t>()>& work,
                                       const std::string& what, const IsolationLimits& limits = {});

}  // namespace ts
