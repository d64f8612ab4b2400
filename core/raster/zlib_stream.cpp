#include "core/raster/zlib_stream.hpp"

#include "core/raster/igzip_stream_home.hpp"

#include <isa-l/igzip_lib.h>
#include <libdeflate.h>

#include <immintrin.h>

#include <array>
#include <memory>
#include <new>
#include <vector>

namespace ts::raster {
namespace {

// One libdeflate compressor per level and thread, kept: allocating one is a malloc of its hash
// tables (hundreds of KB) that a frame sequence would otherwise pay per frame.
libdeflate_compressor* libdeflate_for(int level) {
    struct Free {
        void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
    };
    thread_local std::array<std::unique_ptr<libdeflate_compressor, Free>, 13> cache;
    auto& c = cache[std::size_t(level)];
    if (!c) c.reset(libdeflate_alloc_compressor(level));
    if (!c) throw std::bad_alloc();
    return c.get();
}

// igzip's per-level working memory (its hash tables), kept per thread for the same reason.
std::vector<std::uint8_t>& isal_level_buffer(int level) {
    static constexpr std::array<std::size_t, 4> kSizes = {ISAL_DEF_LVL0_DEFAULT, ISAL_DEF_LVL1_DEFAULT,
                                                          ISAL_DEF_LVL2_DEFAULT, ISAL_DEF_LVL3_DEFAULT};
    thread_local std::array<std::vector<std::uint8_t>, 4> buffers;
    auto& b = buffers[std::size_t(level)];
    if (b.size() < kSizes[std::size_t(level)]) b.resize(kSizes[std::size_t(level)]);
    return b;
}

// igzip's AVX-512 kernels return with the upper halves of the vector registers dirty; the
// SSE code that follows on the same thread (this project builds for baseline x86-64) then pays
// a false dependency on every instruction: sky projection after a PNG ran 10x slower. Clearing
// them is one instruction.
__attribute__((target("avx"))) void clear_upper_vector_state() { _mm256_zeroupper(); }

std::size_t isal_compress(int level, const std::uint8_t* in, std::size_t in_size, std::uint8_t* out,
                          std::size_t out_capacity) {
    // igzip counts in 32-bit lengths; a bigger picture goes to libdeflate.
    if (in_size > 0xffffffffu / 2 || out_capacity > 0xffffffffu) return 0;
    // Zeroed first: isal_deflate_stateless_init leaves fields unset that the stateless path
    // reads, among them the window size, so whatever the memory held decided it (a small number
    // there shrinks the window and changes the bytes). Tiles are compared by hash on resume and
    // merge: the bytes must be a function of the input alone (tests/raster/zlib_stream_test.cpp).
    // The stream's address changes them too (igzip_stream_home.hpp): it lives at one whose hash
    // is the same on every thread; should no such address be free, libdeflate compresses instead.
    isal_zstream* stream = zeroed_igzip_stream_for_this_thread();
    if (!stream) return 0;
    isal_zstream& s = *stream;
    isal_deflate_stateless_init(&s);
    s.hist_bits = 0;  // igzip's default window (32 KiB)
    auto& buffer = isal_level_buffer(level);
    s.level = std::uint32_t(level);
    s.level_buf = buffer.empty() ? nullptr : buffer.data();
    s.level_buf_size = std::uint32_t(buffer.size());
    s.gzip_flag = IGZIP_ZLIB;
    s.end_of_stream = 1;
    s.flush = NO_FLUSH;
    s.next_in = const_cast<std::uint8_t*>(in);  // igzip's API is not const-correct; it only reads
    s.avail_in = std::uint32_t(in_size);
    s.next_out = out;
    s.avail_out = std::uint32_t(out_capacity);
    const int status = isal_deflate_stateless(&s);
    if (__builtin_cpu_supports("avx")) clear_upper_vector_state();
    if (status != COMP_OK || s.avail_in != 0) return 0;
    return s.total_out;
}

}  // namespace

int max_level(Deflater deflater) { return deflater == Deflater::isal ? 3 : 12; }

std::size_t zlib_bound(std::size_t input_size) {
    // Stored blocks cost 5 bytes each; zlib adds a 2-byte header and a 4-byte Adler-32.
    // libdeflate's own bound counts a block per 5000 input bytes (MIN_BLOCK_LENGTH), more than
    // ISA-L's 65535: a bound per 65535 refused its inputs above ~1 MB. Both stay below this.
    return input_size + 5 * (input_size / 4096 + 1) + 6 + 1024;
}

std::size_t zlib_compress(Deflater deflater, int level, const std::uint8_t* in, std::size_t in_size,
                          std::uint8_t* out, std::size_t out_capacity) {
    if (level < 0 || level > max_level(deflater)) return 0;
    if (deflater == Deflater::isal) {
        if (const std::size_t n = isal_compress(level, in, in_size, out, out_capacity)) return n;
        // Overflow or an input too big for igzip's 32-bit counters: libdeflate's fastest level.
        level = 1;
    }
    libdeflate_compressor* c = libdeflate_for(level);
    if (out_capacity < libdeflate_zlib_compress_bound(c, in_size)) return 0;
    return libdeflate_zlib_compress(c, in, in_size, out, out_capacity);
}

}  // namespace ts::raster
