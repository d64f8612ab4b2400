#include "core/dem/block_cache.hpp"

#include <algorithm>

namespace ts::dem {

BlockCache::Block BlockCache::get(std::uint64_t key, const std::function<std::vector<std::uint8_t>()>& decode) {
    std::unique_lock lock(mutex_);
    if (auto it = index_.find(key); it != index_.end()) {
        lru_.splice(lru_.begin(), lru_, it->second);
        return it->second->block;
    }
    if (auto it = pending_.find(key); it != pending_.end()) {
        const std::shared_future<Block> wanted = it->second;
        lock.unlock();
        return wanted.get();
    }
    std::promise<Block> promise;
    pending_.emplace(key, promise.get_future().share());
    ++decodes_;
    lock.unlock();

    Block block;
    try {
        block = std::make_shared<const std::vector<std::uint8_t>>(decode());
    } catch (...) {
        lock.lock();
        pending_.erase(key);
        promise.set_exception(std::current_exception());
        throw;
    }
    lock.lock();
    pending_.erase(key);
    insert(key, block);
    promise.set_value(block);
    return block;
}

void BlockCache::insert(std::uint64_t key, Block block) {
    const std::size_t size = block->size();
    if (size > capacity_) return;
    lru_.push_front({key, std::move(block)});
    index_[key] = lru_.begin();
    bytes_ += size;
    while (bytes_ > capacity_) {
        const Entry& last = lru_.back();
        bytes_ -= last.block->size();
        index_.erase(last.key);
        lru_.pop_back();
    }
    peak_bytes_ = std::max(peak_bytes_, bytes_);
}

std::size_t BlockCache::bytes() const {
    std::lock_guard lock(mutex_);
    return bytes_;
}

std::size_t BlockCache::peak_bytes() const {
    std::lock_guard lock(mutex_);
    return peak_bytes_;
}

std::uint64_t BlockCache::decodes() const {
    std::lock_guard lock(mutex_);
    return decodes_;
}

}  // namespace ts::dem
