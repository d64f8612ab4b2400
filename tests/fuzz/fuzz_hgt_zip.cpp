// libFuzzer target: arbitrary bytes through the hgt.zip reader (dem_fuzz_inputs.hpp says how).
#include <cstddef>
#include <cstdint>

#include "core/util/memory.hpp"
#include "tests/fuzz/dem_fuzz_inputs.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    ts::set_memory_cap(ts::fuzz::kMemoryCap);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ts::fuzz::feed_hgt_zip(data, size);
    return 0;
}
