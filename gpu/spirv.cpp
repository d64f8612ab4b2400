#include "gpu/spirv.hpp"

#include <stdexcept>
#include <string>

namespace ts::gpu {

std::span<const std::uint32_t> spirv(std::string_view name) {
    std::string file_name{name};
    if (file_name.find('.') == std::string::npos) file_name += ".comp";
    for (const SpirvBlob* blob : embedded_shaders()) {
        if (file_name == blob->name) return blob->words;
    }
    throw std::out_of_range("no embedded shader named " + file_name + " (is it in gpu/shaders?)");
}

}  // namespace ts::gpu
