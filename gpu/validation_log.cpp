#include "gpu/validation_log.hpp"

#include <cstdio>

namespace ts::gpu {

void ValidationLog::add(std::string message) {
    std::lock_guard lock(mutex_);
    if (echo_) std::fprintf(stderr, "terrashade: vulkan validation: %s\n", message.c_str());
    messages_.push_back(std::move(message));
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

std::size_t ValidationLog::size() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
}

}  // namespace ts::gpu
