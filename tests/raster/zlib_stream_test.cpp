// zlib_compress is a function of its input, deflater and level only: map tiles, their resume
// and the merge of shards compare tiles by hash, so the bytes must not depend on what the
// calling thread's stack held before. igzip's stateless init leaves the window size
// (hist_bits) unset, and a small number left there by an earlier call shrinks the window.
#include <cstdint>
#include <cstring>
#include <libdeflate.h>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/raster/igzip_stream_home.hpp"
#include "core/raster/zlib_stream.hpp"

namespace ts::raster {
namespace {

// Leaves 32-bit words of `word` in the stack below the caller's frame, where the next call's
// locals go.
__attribute__((noinline)) void scribble_stack(std::uint32_t word) {
    volatile std::uint32_t junk[1 << 16];  // 256 KiB: igzip's stream alone is ~100 KiB
    for (std::size_t k = 0; k < sizeof junk / sizeof junk[0]; ++k) junk[k] = word;
    (void)junk[0];
}

// Grey + alpha rows of a shaded tile: runs of slowly varying values, alpha 255.
std::vector<std::uint8_t> tile_like_bytes(std::uint32_t seed) {
    std::vector<std::uint8_t> v(256 * (1 + 2 * 256));
    std::uint32_t state = seed;
    for (std::size_t k = 0; k < v.size(); ++k) {
        state = state * 1664525u + 1013904223u;
        v[k] = k % 2 ? 255 : std::uint8_t(100 + (k / 512 + seed) % 50 + (state >> 30));
    }
    return v;
}

// A tile at the data's edge: its first `blank` rows transparent (grey 0, alpha 0), the rest as
// tile_like_bytes.
std::vector<std::uint8_t> edge_tile_bytes(std::uint32_t seed, int blank) {
    std::vector<std::uint8_t> v = tile_like_bytes(seed);
    std::fill(v.begin(), v.begin() + std::ptrdiff_t(blank) * (1 + 2 * 256), std::uint8_t(0));
    return v;
}

std::vector<std::uint8_t> compressed(Deflater d, int level, const std::vector<std::uint8_t>& in) {
    std::vector<std::uint8_t> out(zlib_bound(in.size()));
    out.resize(zlib_compress(d, level, in.data(), in.size(), out.data(), out.size()));
    return out;
}

// `in` compressed after another picture went through the same thread's working memory and
// the stack was left holding `stack_word`: what a worker sees after its previous tile.
std::vector<std::uint8_t> compressed_after(const std::vector<std::uint8_t>& other, std::uint32_t stack_word,
                                           Deflater d, int level, const std::vector<std::uint8_t>& in) {
    (void)compressed(d, level, other);
    std::vector<std::uint8_t> out(zlib_bound(in.size()));
    scribble_stack(stack_word);
    out.resize(zlib_compress(d, level, in.data(), in.size(), out.data(), out.size()));
    return out;
}

TEST(ZlibStream, TheBytesDependOnTheInputOnlyNotOnEarlierCallsOrTheStack) {
    const std::vector<std::uint8_t> in = tile_like_bytes(12345);
    for (const Deflater d : {Deflater::isal, Deflater::libdeflate})
        for (int level = 0; level <= max_level(d); ++level) {
            // The reference from a new thread: fresh working memory, a zeroed stack.
            std::vector<std::uint8_t> reference;
            std::thread([&] { reference = compressed(d, level, in); }).join();
            ASSERT_FALSE(reference.empty());
            std::uint32_t seed = 1;
            // Window sizes igzip would take (8..15) in both 16-bit halves (its field is 16-bit),
            // zero, and values it ignores.
            for (const std::uint32_t word : {0u, 0x00080008u, 0x00090009u, 0x000c000cu, 0x000e000eu, 0xffffffffu,
                                             0x5a5a5a5au})
                EXPECT_EQ(compressed_after(tile_like_bytes(seed++), word, d, level, in), reference)
                    << (d == Deflater::isal ? "isal" : "libdeflate") << " level " << level << " after stack words "
                    << word;
        }
}

TEST(ZlibStream, AnEdgeTileDoesNotDependOnTheTilesBeforeIt) {
    // Tiles at the data's edge are long runs of zeros: the deflater's match finder must not take
    // what an earlier picture left in its tables for a match here (resume and merge compare the
    // bytes of such tiles after a different predecessor).
    for (const Deflater d : {Deflater::isal, Deflater::libdeflate})
        for (int level = 0; level <= max_level(d); ++level)
            for (int blank : {40, 128, 250}) {
                const std::vector<std::uint8_t> in = edge_tile_bytes(777, blank);
                std::vector<std::uint8_t> reference;
                std::thread([&] { reference = compressed(d, level, in); }).join();
                std::uint32_t seed = 1;
                for (int other_blank : {0, 17, 64, 200, 255})
                    EXPECT_EQ(compressed_after(edge_tile_bytes(seed++, other_blank), 0u, d, level, in), reference)
                        << (d == Deflater::isal ? "isal" : "libdeflate") << " level " << level << ", " << blank
                        << " blank rows after a tile with " << other_blank;
            }
}

// igzip's level-1 kernel files the input's third byte under a hash of the address of its stream
// structure (core/raster/igzip_stream_home.hpp). That only changes the bytes when the slot is
// the one a later match needs: here bytes 5..8 repeat bytes 1..4, which the kernel finds unless
// the address hashes to their slot. Inputs of 1500 bytes (igzip masks their hashes to 10 bits)
// with such a repeat, several per slot, so that whichever slot a thread's address gives, some
// inputs need it (with the stream on the caller's stack this test failed 10 runs in 10).
std::vector<std::vector<std::uint8_t>> inputs_for_every_hash_slot() {
    constexpr std::uint32_t kSlots = 1024, kPerSlot = 4;  // not every repeat is one the kernel takes
    std::vector<std::uint32_t> count(kSlots);
    std::vector<std::vector<std::uint8_t>> inputs;
    for (std::uint32_t word = 0x01020304u; inputs.size() < kSlots * kPerSlot; word = word * 747796405u + 2891336453u) {
        if (count[igzip_address_hash(std::uintptr_t(word) << 16) % kSlots]++ >= kPerSlot) continue;
        std::vector<std::uint8_t> in(1500);
        std::uint32_t state = word;
        for (std::size_t k = 0; k < in.size(); ++k) {  // grey + alpha, compressible as a tile is
            state = state * 1664525u + 1013904223u;
            in[k] = k % 2 ? 255 : std::uint8_t(100 + (k / 64) % 50 + (state >> 30));
        }
        in[0] = 0x5a;
        for (int k = 0; k < 4; ++k) in[std::size_t(1 + k)] = in[std::size_t(5 + k)] = std::uint8_t(word >> (8 * k));
        inputs.push_back(std::move(in));
    }
    return inputs;
}

TEST(ZlibStream, TheBytesDoNotDependOnWhichThreadCompresses) {
    // Before the stream had its own address, a map tile in ~1 run in 6 of a two-thread export
    // got other deflate bytes than in a one-thread run (same pixels): resume and shard merge
    // compare tiles by hash. Threads have their stacks at different addresses.
    const auto inputs = inputs_for_every_hash_slot();
    auto compress_all = [&] {
        std::vector<std::vector<std::uint8_t>> out;
        for (const auto& in : inputs) out.push_back(compressed(Deflater::isal, 1, in));
        return out;
    };
    const auto on_this_thread = compress_all();
    for (int t = 0; t < 3; ++t) {
        std::vector<std::vector<std::uint8_t>> on_another;
        std::thread([&] { on_another = compress_all(); }).join();
        for (std::size_t k = 0; k < inputs.size(); ++k)
            ASSERT_EQ(on_another[k], on_this_thread[k]) << "input " << k << ", thread " << t;
    }
    // And the streams are right.
    libdeflate_decompressor* d = libdeflate_alloc_decompressor();
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        std::vector<std::uint8_t> back(inputs[k].size());
        std::size_t n = 0;
        ASSERT_EQ(libdeflate_zlib_decompress(d, on_this_thread[k].data(), on_this_thread[k].size(), back.data(),
                                             back.size(), &n),
                  LIBDEFLATE_SUCCESS);
        EXPECT_EQ(back, inputs[k]);
    }
    libdeflate_free_decompressor(d);
}

}  // namespace
}  // namespace ts::raster
