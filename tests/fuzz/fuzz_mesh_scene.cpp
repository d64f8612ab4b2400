// libFuzzer target: arbitrary bytes as the importer's scene record, decoded and flattened (mesh_fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/mesh_fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ts::fuzz::feed_mesh_scene(data, size);
    return 0;
}
