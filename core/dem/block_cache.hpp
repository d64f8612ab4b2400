#pragma once
// Decoded blocks of DEM files (an .hgt.zip's inflated entry, GeoTIFF strips and tiles) kept
// between window reads, least recently used evicted first, never more than a byte budget.
// Thread-safe. A block that is being decoded is decoded once: other threads wanting it wait
// for it instead of decoding it again.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <future>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace ts::dem {

class BlockCache {
public:
    // Readers hold a block through this while they copy from it, so evicting it never pulls
    // bytes from under them.
    using Block = std::shared_ptr<const std::vector<std::uint8_t>>;

    explicit BlockCache(std::size_t capacity_bytes) : capacity_(capacity_bytes) {}

    // The block `key`, from the cache or from `decode` (whose exceptions reach every caller
    // waiting for that key; nothing is cached then). A block larger than the whole budget is
    // returned but not kept.
    Block get(std::uint64_t key, const std::function<std::vector<std::uint8_t>()>& decode);

    std::size_t bytes() const;
    std::size_t peak_bytes() const;
    // How many times `decode` ran: what reads have cost in decoding.
    std::uint64_t decodes() const;

private:
    struct Entry {
        std::uint64_t key;
        Block block;
    };
    // Under mutex_: makes `key` the most recently used, keeps the budget.
    void insert(std::uint64_t key, Block block);

    const std::size_t capacity_;
    mutable std::mutex mutex_;
    std::list<Entry> lru_;  // most recently used first
    std::unordered_map<std::uint64_t, std::list<Entry>::iterator> index_;
    std::unordered_map<std::uint64_t, std::shared_future<Block>> pending_;
    std::size_t bytes_ = 0, peak_bytes_ = 0;
    std::uint64_t decodes_ = 0;
};

}  // namespace ts::dem
