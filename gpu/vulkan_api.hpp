#pragma once
// Vulkan without linking libvulkan: the loader (libvulkan.so.1) is opened at run time, the
// first time a gpu::Instance is made, and every core function below is looked up in it once.
// So terrashade starts, and runs its CPU commands, on a machine with no Vulkan at all, and a
// missing loader becomes a one-line ts::InputError naming the package instead of a dynamic
// linker failure before main.
//
// Code in namespace ts::gpu calls the functions by their usual names (vkCreateBuffer(...)):
// they are function pointers in ts::gpu::vulkan_functions, brought in below. A function not
// listed here is not declared (VK_NO_PROTOTYPES): add it to TS_GPU_VULKAN_FUNCTIONS. Extension
// functions are reached through vkGetInstanceProcAddr as usual.
#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan.h>

// Core Vulkan 1.0/1.1 functions terrashade uses; the loader exports each under this name.
#define TS_GPU_VULKAN_FUNCTIONS(X)           \
    X(vkGetInstanceProcAddr)                 \
    X(vkEnumerateInstanceVersion)            \
    X(vkEnumerateInstanceLayerProperties)    \
    X(vkEnumerateInstanceExtensionProperties) \
    X(vkCreateInstance)                      \
    X(vkDestroyInstance)                     \
    X(vkEnumeratePhysicalDevices)            \
    X(vkGetPhysicalDeviceProperties)         \
    X(vkGetPhysicalDeviceFeatures)           \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkGetPhysicalDeviceMemoryProperties)   \
    X(vkGetPhysicalDeviceFormatProperties)   \
    X(vkEnumerateDeviceExtensionProperties)  \
    X(vkCreateDevice)                        \
    X(vkDestroyDevice)                       \
    X(vkGetDeviceProcAddr)                   \
    X(vkGetDeviceQueue)                      \
    X(vkDeviceWaitIdle)                      \
    X(vkQueueSubmit)                         \
    X(vkQueueWaitIdle)                       \
    X(vkCreateCommandPool)                   \
    X(vkDestroyCommandPool)                  \
    X(vkResetCommandPool)                    \
    X(vkAllocateCommandBuffers)              \
    X(vkFreeCommandBuffers)                  \
    X(vkBeginCommandBuffer)                  \
    X(vkEndCommandBuffer)                    \
    X(vkResetCommandBuffer)                  \
    X(vkCreateFence)                         \
    X(vkDestroyFence)                        \
    X(vkWaitForFences)                       \
    X(vkResetFences)                         \
    X(vkGetFenceStatus)                      \
    X(vkCreateSemaphore)                     \
    X(vkDestroySemaphore)                    \
    X(vkCreateBuffer)                        \
    X(vkDestroyBuffer)                       \
    X(vkGetBufferMemoryRequirements)         \
    X(vkBindBufferMemory)                    \
    X(vkCreateImage)                         \
    X(vkDestroyImage)                        \
    X(vkGetImageMemoryRequirements)          \
    X(vkBindImageMemory)                     \
    X(vkCreateImageView)                     \
    X(vkDestroyImageView)                    \
    X(vkCreateSampler)                       \
    X(vkDestroySampler)                      \
    X(vkAllocateMemory)                      \
    X(vkFreeMemory)                          \
    X(vkMapMemory)                           \
    X(vkUnmapMemory)                         \
    X(vkFlushMappedMemoryRanges)             \
    X(vkInvalidateMappedMemoryRanges)        \
    X(vkCreateDescriptorSetLayout)           \
    X(vkDestroyDescriptorSetLayout)          \
    X(vkCreateDescriptorPool)                \
    X(vkDestroyDescriptorPool)               \
    X(vkResetDescriptorPool)                 \
    X(vkAllocateDescriptorSets)              \
    X(vkFreeDescriptorSets)                  \
    X(vkUpdateDescriptorSets)                \
    X(vkCreateShaderModule)                  \
    X(vkDestroyShaderModule)                 \
    X(vkCreatePipelineLayout)                \
    X(vkDestroyPipelineLayout)               \
    X(vkCreateComputePipelines)              \
    X(vkDestroyPipeline)                     \
    X(vkCreateQueryPool)                     \
    X(vkDestroyQueryPool)                    \
    X(vkGetQueryPoolResults)                 \
    X(vkCmdBindPipeline)                     \
    X(vkCmdBindDescriptorSets)               \
    X(vkCmdPushConstants)                    \
    X(vkCmdDispatch)                         \
    X(vkCmdPipelineBarrier)                  \
    X(vkCmdCopyBuffer)                       \
    X(vkCmdCopyBufferToImage)                \
    X(vkCmdCopyImageToBuffer)                \
    X(vkCmdFillBuffer)                       \
    X(vkCmdUpdateBuffer)                     \
    X(vkCmdResetQueryPool)                   \
    X(vkCmdWriteTimestamp)                   \
    X(vkCreateRenderPass)                    \
    X(vkDestroyRenderPass)                   \
    X(vkCreateFramebuffer)                   \
    X(vkDestroyFramebuffer)                  \
    X(vkCreateGraphicsPipelines)             \
    X(vkCmdBeginRenderPass)                  \
    X(vkCmdEndRenderPass)                    \
    X(vkCmdDraw)                             \
    X(vkCmdDrawIndexed)                      \
    X(vkCmdBindIndexBuffer)                  \
    X(vkCmdSetViewport)                      \
    X(vkCmdSetScissor)                       \
    X(vkCmdBlitImage)

namespace ts::gpu {
namespace vulkan_functions {
// Set once by load_vulkan() (under std::call_once), read-only after.
#define TS_GPU_DECLARE_FUNCTION(name) extern PFN_##name name;
TS_GPU_VULKAN_FUNCTIONS(TS_GPU_DECLARE_FUNCTION)
#undef TS_GPU_DECLARE_FUNCTION
}  // namespace vulkan_functions
using namespace vulkan_functions;

// Opens the Vulkan loader and resolves every function above, once per process; later calls
// return at once. Throws ts::InputError naming the package when the loader is missing.
// The variable TERRASHADE_VULKAN_LIBRARY names another loader file (tests use it to simulate a
// machine without one).
void load_vulkan();

}  // namespace ts::gpu
