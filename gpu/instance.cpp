#include "gpu/instance.hpp"

#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "gpu/debug_messenger.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
    std::uint32_t count = 0;
    check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
    std::vector<VkLayerProperties> layers(count);
    check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties");
    for (const auto& layer : layers) {
        if (std::strcmp(layer.layerName, name) == 0) return true;
    }
    return false;
}

// An extension of the loader and drivers (layer == nullptr) or of one layer.
bool has_instance_extension(const char* name, const char* layer = nullptr) {
    std::uint32_t count = 0;
    check(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr), "vkEnumerateInstanceExtensionProperties");
    std::vector<VkExtensionProperties> extensions(count);
    check(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()),
          "vkEnumerateInstanceExtensionProperties");
    for (const auto& extension : extensions) {
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    }
    return false;
}

}  // namespace

InputError no_vulkan_device_error(const std::string& detail) {
    return InputError("vulkan: " + detail +
                      "; install mesa-vulkan-drivers (lavapipe runs Vulkan on the CPU) or your GPU's Vulkan "
                      "driver");
}

bool validation_requested_by_environment() {
    const char* value = std::getenv("TERRASHADE_VALIDATION");
    return value != nullptr && std::strcmp(value, "1") == 0;
}

Instance::Instance(const InstanceOptions& options) : validation_(options.validation) {
    load_vulkan();
    std::uint32_t loader_version = VK_API_VERSION_1_0;
    check(vkEnumerateInstanceVersion(&loader_version), "vkEnumerateInstanceVersion");
    if (loader_version < VK_API_VERSION_1_1) {
        throw no_vulkan_device_error("the Vulkan loader is older than 1.1");
    }

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
    const VkValidationFeatureEnableEXT enabled_features[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    const void* chain = nullptr;
    if (validation_) {
        if (options.log == nullptr) throw std::logic_error("gpu::Instance: validation needs a ValidationLog");
        if (!has_layer(kValidationLayer)) {
            throw InputError(std::string("vulkan: validation was requested but ") + kValidationLayer +
                             " is not installed; install vulkan-validationlayers");
        }
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        // Chained here, the messenger also reports on vkCreateInstance and vkDestroyInstance.
        messenger_info = debug_messenger_create_info(*options.log);
        chain = &messenger_info;
        if (options.synchronization_validation &&
            has_instance_extension(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, kValidationLayer)) {
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            features.enabledValidationFeatureCount = 1;
            features.pEnabledValidationFeatures = enabled_features;
            features.pNext = chain;
            chain = &features;
        }
    }
    for (const std::string& name : options.extensions) {
        if (!has_instance_extension(name.c_str())) {
            throw InputError("vulkan: the instance extension " + name + " is missing; install libvulkan1 and a driver with window-system support");
        }
        extensions.push_back(name.c_str());
    }
    // Drivers layered over another API (MoltenVK) are listed only when asked for; harmless elsewhere.
    VkInstanceCreateFlags flags = 0;
    if (has_instance_extension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }

    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "terrashade";
    app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.pEngineName = "terrashade";
    app.engineVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.apiVersion = VK_API_VERSION_1_1;

    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = chain;
    info.flags = flags;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    const VkResult result = vkCreateInstance(&info, nullptr, &instance_);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
        throw no_vulkan_device_error("no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER)");
    }
    check(result, "vkCreateInstance");
}

Instance::~Instance() {
    if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

Instance::Instance(Instance&& other) noexcept
    : instance_(std::exchange(other.instance_, VK_NULL_HANDLE)), validation_(other.validation_) {}

Instance& Instance::operator=(Instance&& other) noexcept {
    if (this != &other) {
        if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
        instance_ = std::exchange(other.instance_, VK_NULL_HANDLE);
        validation_ = other.validation_;
    }
    return *this;
}

}  // namespace ts::gpu
