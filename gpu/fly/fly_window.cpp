#include "gpu/fly/fly_window.hpp"

#include <algorithm>
#include <cstdlib>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "core/util/error.hpp"
#include "gpu/fly/gpu_image.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu {

// The surface and swapchain functions are extensions: looked up once per window.
struct FlyWindow::Functions {
    PFN_vkDestroySurfaceKHR destroy_surface = nullptr;
    PFN_vkGetPhysicalDeviceSurfaceSupportKHR surface_support = nullptr;
    PFN_vkGetPhysicalDeviceSurfaceCapabilitiesKHR capabilities = nullptr;
    PFN_vkGetPhysicalDeviceSurfaceFormatsKHR formats = nullptr;
    PFN_vkGetPhysicalDeviceSurfacePresentModesKHR present_modes = nullptr;
    PFN_vkCreateSwapchainKHR create_swapchain = nullptr;
    PFN_vkDestroySwapchainKHR destroy_swapchain = nullptr;
    PFN_vkGetSwapchainImagesKHR swapchain_images = nullptr;
    PFN_vkAcquireNextImageKHR acquire = nullptr;
    PFN_vkQueuePresentKHR present = nullptr;
};

namespace {

template <typename F>
F instance_function(VkInstance instance, const char* name) {
    auto f = reinterpret_cast<F>(vkGetInstanceProcAddr(instance, name));
    if (f == nullptr) throw InputError(std::string("vulkan: the driver lacks ") + name + " (no window-system support)");
    return f;
}

DeviceHandle<VkSemaphore> make_semaphore(VkDevice device) {
    VkSemaphoreCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore s = VK_NULL_HANDLE;
    check(vkCreateSemaphore(device, &info, nullptr, &s), "vkCreateSemaphore");
    return {device, s, vkDestroySemaphore};
}

}  // namespace

bool display_available(std::string& reason) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0')) {
        reason = "no display (DISPLAY is not set)";
        return false;
    }
    if (glfwInit() != GLFW_TRUE) {
        reason = std::string("cannot open the display ") + (display ? display : "");
        return false;
    }
    return true;
}

namespace {
std::string glfw_error() {
    const char* what = nullptr;
    glfwGetError(&what);
    return what != nullptr ? std::string(": ") + what : std::string();
}
}  // namespace

FlyWindow::FlyWindow(int width, int height, const std::string& title) {
    if (glfwInit() != GLFW_TRUE) throw InputError("fly: cannot open a window (GLFW could not start" + glfw_error() + ")");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const std::string why = glfw_error();
        glfwTerminate();
        throw InputError("fly: cannot open a window on this display" + why);
    }
}

FlyWindow::~FlyWindow() {
    if (context_ != nullptr) {
        context_->device().wait_idle();
        destroy_swapchain();
        if (surface_ != VK_NULL_HANDLE) fn_->destroy_surface(context_->vk_instance(), surface_, nullptr);
    }
    // The semaphores, fence and command buffer go with their members, before glfwTerminate
    // has no bearing on them; the window goes last.
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> FlyWindow::instance_extensions() {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (names == nullptr) throw InputError("fly: the Vulkan loader offers no window-system surface for this display");
    return std::vector<std::string>(names, names + count);
}

void FlyWindow::attach(const Context& context, bool vsync) {
    context_ = &context;
    vsync_ = vsync;
    fn_ = std::make_unique<Functions>();
    const VkInstance instance = context.vk_instance();
    fn_->destroy_surface = instance_function<PFN_vkDestroySurfaceKHR>(instance, "vkDestroySurfaceKHR");
    fn_->surface_support =
        instance_function<PFN_vkGetPhysicalDeviceSurfaceSupportKHR>(instance, "vkGetPhysicalDeviceSurfaceSupportKHR");
    fn_->capabilities = instance_function<PFN_vkGetPhysicalDeviceSurfaceCapabilitiesKHR>(
        instance, "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    fn_->formats =
        instance_function<PFN_vkGetPhysicalDeviceSurfaceFormatsKHR>(instance, "vkGetPhysicalDeviceSurfaceFormatsKHR");
    fn_->present_modes = instance_function<PFN_vkGetPhysicalDeviceSurfacePresentModesKHR>(
        instance, "vkGetPhysicalDeviceSurfacePresentModesKHR");
    fn_->create_swapchain = instance_function<PFN_vkCreateSwapchainKHR>(instance, "vkCreateSwapchainKHR");
    fn_->destroy_swapchain = instance_function<PFN_vkDestroySwapchainKHR>(instance, "vkDestroySwapchainKHR");
    fn_->swapchain_images = instance_function<PFN_vkGetSwapchainImagesKHR>(instance, "vkGetSwapchainImagesKHR");
    fn_->acquire = instance_function<PFN_vkAcquireNextImageKHR>(instance, "vkAcquireNextImageKHR");
    fn_->present = instance_function<PFN_vkQueuePresentKHR>(instance, "vkQueuePresentKHR");

    check(glfwCreateWindowSurface(instance, window_, nullptr, &surface_), "glfwCreateWindowSurface");
    VkBool32 supported = VK_FALSE;
    check(fn_->surface_support(context.device().physical(), context.device().queue_family(), surface_, &supported),
          "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported) throw InputError("fly: the Vulkan device cannot present to this window");
    const VkDevice device = context.vk_device();
    pool_ = CommandPool(device, context.device().queue_family());
    commands_ = CommandBuffer(device, pool_);
    fence_ = Fence(device);
    acquired_ = make_semaphore(device);
    rendered_ = make_semaphore(device);
    create_swapchain();
}

void FlyWindow::create_swapchain() {
    const VkPhysicalDevice physical = context_->device().physical();
    VkSurfaceCapabilitiesKHR caps{};
    check(fn_->capabilities(physical, surface_, &caps), "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    extent_ = caps.currentExtent.width != 0xFFFFFFFFu
                  ? caps.currentExtent
                  : VkExtent2D{std::clamp(std::uint32_t(fw), caps.minImageExtent.width, caps.maxImageExtent.width),
                               std::clamp(std::uint32_t(fh), caps.minImageExtent.height, caps.maxImageExtent.height)};
    if (extent_.width == 0 || extent_.height == 0) return;  // minimised: try again later
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw InputError("fly: the window's swapchain images cannot be copied into");

    std::uint32_t count = 0;
    check(fn_->formats(physical, surface_, &count, nullptr), "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(count);
    check(fn_->formats(physical, surface_, &count, formats.data()), "vkGetPhysicalDeviceSurfaceFormatsKHR");
    // The colour target is already display-encoded: a UNORM swapchain keeps the codes as they are.
    VkSurfaceFormatKHR format = formats.front();
    for (const auto& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) format = f;

    check(fn_->present_modes(physical, surface_, &count, nullptr), "vkGetPhysicalDeviceSurfacePresentModesKHR");
    std::vector<VkPresentModeKHR> modes(count);
    check(fn_->present_modes(physical, surface_, &count, modes.data()), "vkGetPhysicalDeviceSurfacePresentModesKHR");
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;
    if (!vsync_) {
        for (auto m : modes)
            if (m == VK_PRESENT_MODE_IMMEDIATE_KHR) mode = m;
        for (auto m : modes)
            if (m == VK_PRESENT_MODE_MAILBOX_KHR) mode = m;
    }

    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = surface_;
    info.minImageCount = caps.maxImageCount == 0 ? caps.minImageCount + 1
                                                 : std::min(caps.minImageCount + 1, caps.maxImageCount);
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
        info.compositeAlpha = VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    info.presentMode = mode;
    info.clipped = VK_TRUE;
    const VkDevice device = context_->vk_device();
    check(fn_->create_swapchain(device, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
    check(fn_->swapchain_images(device, swapchain_, &count, nullptr), "vkGetSwapchainImagesKHR");
    images_.resize(count);
    check(fn_->swapchain_images(device, swapchain_, &count, images_.data()), "vkGetSwapchainImagesKHR");
}

void FlyWindow::destroy_swapchain() {
    if (swapchain_ != VK_NULL_HANDLE) fn_->destroy_swapchain(context_->vk_device(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    images_.clear();
}

void FlyWindow::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

bool FlyWindow::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void FlyWindow::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

WindowInput FlyWindow::poll() {
    static constexpr int kKeys[] = {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E,
                                    GLFW_KEY_R, GLFW_KEY_F, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_UP, GLFW_KEY_DOWN,
                                    GLFW_KEY_LEFT, GLFW_KEY_RIGHT};
    static constexpr int kPressKeys[] = {GLFW_KEY_ESCAPE, GLFW_KEY_C, GLFW_KEY_O, GLFW_KEY_V, GLFW_KEY_P,
                                         GLFW_KEY_F12, GLFW_KEY_LEFT_BRACKET, GLFW_KEY_RIGHT_BRACKET,
                                         GLFW_KEY_COMMA, GLFW_KEY_PERIOD, GLFW_KEY_EQUAL, GLFW_KEY_MINUS,
                                         GLFW_KEY_SPACE, GLFW_KEY_K, GLFW_KEY_H, GLFW_KEY_F1};
    // Edge detection is done here (no callbacks: no state shared through a global).
    static_assert(sizeof(kPressKeys) / sizeof(int) < 64);
    WindowInput in;
    double x0 = 0, y0 = 0;
    glfwGetCursorPos(window_, &x0, &y0);
    glfwPollEvents();
    double x1 = 0, y1 = 0;
    glfwGetCursorPos(window_, &x1, &y1);
    if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) in.mouse_dx = x1 - x0, in.mouse_dy = y1 - y0;
    for (int key : kKeys)
        if (glfwGetKey(window_, key) == GLFW_PRESS) in.held.push_back(key);
    for (std::size_t i = 0; i < sizeof(kPressKeys) / sizeof(int); ++i) {
        const bool down = glfwGetKey(window_, kPressKeys[i]) == GLFW_PRESS;
        const std::uint64_t bit = std::uint64_t(1) << i;
        if (down && !(key_state_ & bit)) in.pressed.push_back(kPressKeys[i]);
        key_state_ = down ? (key_state_ | bit) : (key_state_ & ~bit);
    }
    in.close = should_close();
    return in;
}

bool FlyWindow::begin(std::uint32_t& index) {
    if (swapchain_ == VK_NULL_HANDLE) {
        create_swapchain();
        if (swapchain_ == VK_NULL_HANDLE) return false;
    }
    const VkResult r =
        fn_->acquire(context_->vk_device(), swapchain_, UINT64_MAX, acquired_.get(), VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        context_->device().wait_idle();
        destroy_swapchain();
        return false;
    }
    if (r != VK_SUBOPTIMAL_KHR) check(r, "vkAcquireNextImageKHR");
    commands_.reset();
    commands_.begin();
    return true;
}

bool FlyWindow::end(VkImage source, int width, int height, std::uint32_t index) {
    const VkCommandBuffer cmd = commands_.get();
    const VkImage target = images_[index];
    transition_image(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {width, height, 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.dstOffsets[1] = {int(extent_.width), int(extent_.height), 1};
    vkCmdBlitImage(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                   &blit, VK_FILTER_NEAREST);
    transition_image(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_ACCESS_TRANSFER_WRITE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
    commands_.end();

    const VkSemaphore wait = acquired_.get(), signal = rendered_.get();
    const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &wait;
    submit.pWaitDstStageMask = &wait_stage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &signal;
    check(vkQueueSubmit(context_->device().queue(), 1, &submit, fence_.get()), "vkQueueSubmit");

    VkPresentInfoKHR present{};
    present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &signal;
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &index;
    const VkResult r = fn_->present(context_->device().queue(), &present);
    fence_.wait();
    fence_.reset();
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR || std::uint32_t(fw) != extent_.width ||
        std::uint32_t(fh) != extent_.height) {
        context_->device().wait_idle();
        destroy_swapchain();
        return false;
    }
    check(r, "vkQueuePresentKHR");
    return true;
}

}  // namespace ts::gpu
