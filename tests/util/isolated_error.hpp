// What ts::run_isolated reports for a piece of work: its one-line error, or "" when it returned.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/util/error.hpp"
#include "core/util/isolated_call.hpp"

namespace ts::test {

using Bytes = std::vector<std::uint8_t>;

inline std::string error_of(const std::function<Bytes()>& work, const IsolationLimits& limits = {}) {
    try {
        run_isolated(work, "model.obj", limits);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace ts::test
