#include "core/raster/igzip_stream_home.hpp"

#include <isa-l/igzip_lib.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstring>

namespace ts::raster {
namespace {

// CRC-32C of one little-endian 32-bit word from 0, without final inversion: what the `crc32`
// instruction computes in igzip's compute_hash macro.
std::uint32_t crc32c_word(std::uint32_t word) {
    std::uint32_t crc = 0;
    for (int byte = 0; byte < 4; ++byte) {
        crc ^= (word >> (8 * byte)) & 0xffu;
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0x82f63b78u & (0u - (crc & 1u)));
    }
    return crc;
}

constexpr std::size_t kMappingSize = (sizeof(isal_zstream) + 4095) & ~std::size_t(4095);

// One mapping per thread, unmapped when the thread ends.
struct StreamHome {
    void* address = nullptr;

    StreamHome() {
        // Candidates are 64 KiB-aligned addresses from 32 TiB up (above where the heap, the
        // libraries, thread stacks and the sanitizers' shadow memory usually live); about one
        // 64 KiB block in 65536 qualifies, and a candidate already in use is skipped.
        std::uint64_t block = (std::uint64_t(1) << 45) >> 16;
        for (int tries = 0; tries < 4096 && !address; ++block) {
            if ((igzip_address_hash(std::uintptr_t(block << 16)) & 0xffffu) != 0) continue;
            ++tries;
            void* wanted = reinterpret_cast<void*>(std::uintptr_t(block << 16));
            void* got = mmap(wanted, kMappingSize, PROT_READ | PROT_WRITE,
                             MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED_NOREPLACE, -1, 0);
            if (got == MAP_FAILED) continue;
            if (got == wanted) {
                address = got;
            } else {
                munmap(got, kMappingSize);  // a kernel older than 4.17 took the address as a hint
            }
        }
    }
    ~StreamHome() {
        if (address) munmap(address, kMappingSize);
    }
    StreamHome(const StreamHome&) = delete;
    StreamHome& operator=(const StreamHome&) = delete;
};

}  // namespace

std::uint32_t igzip_address_hash(std::uintptr_t address) {
    return crc32c_word(std::uint32_t(std::uint64_t(address) >> 16));
}

isal_zstream* zeroed_igzip_stream_for_this_thread() {
    thread_local StreamHome home;
    if (!home.address) return nullptr;
    std::memset(home.address, 0, sizeof(isal_zstream));
    return static_cast<isal_zstream*>(home.address);
}

}  // namespace ts::raster
