#pragma once
// Shaders embedded in the executable as SPIR-V words (compiled from gpu/shaders at build time
// by glslangValidator; see gpu/CMakeLists.txt). No file is read at run time.
#include <cstdint>
#include <span>
#include <string_view>

namespace ts::gpu {

// One compiled shader: its source file name ("vis_exact_sweep.comp") and its SPIR-V words.
struct SpirvBlob {
    const char* name;
    std::span<const std::uint32_t> words;
};

// Every shader of gpu/shaders, in file-name order.
std::span<const SpirvBlob* const> embedded_shaders();

// The SPIR-V of gpu/shaders/<name>; "name" alone means "name.comp". Throws std::out_of_range
// naming the shader if there is none (a build problem, not bad user input).
std::span<const std::uint32_t> spirv(std::string_view name);

}  // namespace ts::gpu
