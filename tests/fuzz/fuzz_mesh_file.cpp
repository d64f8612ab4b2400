// libFuzzer target: arbitrary bytes as a mesh file, assimp in a child process (mesh_fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/mesh_fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ts::fuzz::feed_mesh_file(data, size);
    return 0;
}
