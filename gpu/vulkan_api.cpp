#include "gpu/vulkan_api.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>

#include "core/util/error.hpp"

namespace ts::gpu {
namespace vulkan_functions {
#define TS_GPU_DEFINE_FUNCTION(name) PFN_##name name = nullptr;
TS_GPU_VULKAN_FUNCTIONS(TS_GPU_DEFINE_FUNCTION)
#undef TS_GPU_DEFINE_FUNCTION
}  // namespace vulkan_functions

namespace {

#ifdef __APPLE__
constexpr const char* kLoaderLibrary = "libvulkan.1.dylib";
#else
constexpr const char* kLoaderLibrary = "libvulkan.so.1";
#endif

void open_and_resolve() {
    const char* override_name = std::getenv("TERRASHADE_VULKAN_LIBRARY");
    const std::string library = override_name != nullptr && *override_name != '\0' ? override_name : kLoaderLibrary;
    // Never closed: the functions stay valid for the life of the process.
    void* loader = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (loader == nullptr) {
        throw InputError("vulkan: cannot load the Vulkan loader " + library +
                         "; install libvulkan1 and mesa-vulkan-drivers (lavapipe runs Vulkan on the CPU) or your "
                         "GPU's Vulkan driver");
    }
    std::string missing;
#define TS_GPU_RESOLVE_FUNCTION(name)                                            \
    vulkan_functions::name = reinterpret_cast<PFN_##name>(dlsym(loader, #name)); \
    if (vulkan_functions::name == nullptr) missing += (missing.empty() ? "" : ", ") + std::string(#name);
    TS_GPU_VULKAN_FUNCTIONS(TS_GPU_RESOLVE_FUNCTION)
#undef TS_GPU_RESOLVE_FUNCTION
    if (!missing.empty()) {
        throw InputError("vulkan: the Vulkan loader " + library + " is older than Vulkan 1.1 (it lacks " + missing +
                         "); install a newer libvulkan1");
    }
}

}  // namespace

void load_vulkan() {
    static std::once_flag loaded;
    std::call_once(loaded, open_and_resolve);  // an exception leaves it unloaded for a retry
}

}  // namespace ts::gpu
