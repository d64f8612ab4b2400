#pragma once
// Where igzip's stream structure lives while it compresses, chosen so that its address cannot
// change the bytes.
//
// ISA-L's level-1 kernel (igzip_icf_body_h1_gr_bt.asm, unchanged up to 2.32) hashes the input's
// third byte at the start of a stream from a register that holds, at that point, the address of
// the isal_zstream (`shr tmp2, 16` in .write_first_byte, tmp2 being rcx, which the kernel
// loaded with the stream pointer). Position 2 is thus filed under
// crc32c(uint32(address >> 16)) & hash_mask instead of its own hash. The stream stays valid, but
// when that slot is one a later match depends on (about 2 addresses in 8192 for a map tile) the
// bytes differ: a tile encoded on another thread's stack, or in another run, got other bytes.
//
// The stream is therefore kept, per thread, at an address whose hash is 0 for every mask the
// kernel uses (the low 16 bits of the CRC are 0), so every thread files position 2 in slot 0.
#include <cstdint>

struct isal_zstream;

namespace ts::raster {

// This thread's igzip stream, zeroed; nullptr if no such address could be mapped (the caller
// then compresses with a deflater whose output does not depend on addresses).
isal_zstream* zeroed_igzip_stream_for_this_thread();

// The slot igzip's level-1 kernel files position 2 under for a stream at `address`, before
// masking (exposed for the tests).
std::uint32_t igzip_address_hash(std::uintptr_t address);

}  // namespace ts::raster
