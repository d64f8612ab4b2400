#pragma once
// The flythrough's window: GLFW (X11) without a client API, a Vulkan surface and swapchain,
// and present() that blits the renderer's colour target into the next swapchain image. Resizing
// recreates the swapchain (and the caller resizes the renderer to framebuffer_size()).
//
//   if (!gpu::display_available(reason)) ...            // before any heavy work
//   gpu::FlyWindow window(960, 540, "terrashade fly");  // then a Context with its extensions
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gpu/command.hpp"
#include "gpu/context.hpp"
#include "gpu/handle.hpp"
#include "gpu/vulkan_api.hpp"

struct GLFWwindow;

namespace ts::gpu {

// Whether GLFW can open a window here; when not, `reason` says why in a few words. On success
// GLFW stays initialised (its display connection open) for the FlyWindow that follows, which
// terminates it: closing an X server's last connection makes the server reset, and a
// connection opened during the reset is refused (Xvfb, with no other client, did so for most
// runs started on a loaded machine).
bool display_available(std::string& reason);

struct WindowInput {
    // Keys held this frame, as GLFW key codes (GLFW_KEY_*), and keys pressed since the last poll.
    std::vector<int> held, pressed;
    double mouse_dx = 0, mouse_dy = 0;  // pixels moved with the left button down
    bool close = false;
};

class FlyWindow {
public:
    FlyWindow(int width, int height, const std::string& title);
    ~FlyWindow();
    FlyWindow(const FlyWindow&) = delete;
    FlyWindow& operator=(const FlyWindow&) = delete;

    // What the Context must enable for this window's surface and swapchain.
    static std::vector<std::string> instance_extensions();
    static std::vector<std::string> device_extensions() { return {"VK_KHR_swapchain"}; }

    // After the Context exists: the surface and the first swapchain. `vsync` false asks for a
    // mailbox or immediate present mode when there is one.
    void attach(const Context& context, bool vsync);

    void set_title(const std::string& title);
    WindowInput poll();
    bool should_close() const;
    // The drawable size in pixels (0 x 0 while minimised).
    void framebuffer_size(int& width, int& height) const;

    // One frame: begin() acquires the next swapchain image and begins commands(); the caller
    // records its render pass into commands(); end() blits `source` (TRANSFER_SRC_OPTIMAL,
    // width x height) into the image, submits, presents and waits. Both return false when the
    // swapchain had to be recreated (the frame is skipped; after a false begin() do not call end()).
    bool begin(std::uint32_t& image_index);
    VkCommandBuffer commands() const { return commands_.get(); }
    bool end(VkImage source, int width, int height, std::uint32_t image_index);

private:
    void create_swapchain();
    void destroy_swapchain();

    GLFWwindow* window_ = nullptr;
    const Context* context_ = nullptr;
    bool vsync_ = true;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{0, 0};
    std::vector<VkImage> images_;
    CommandPool pool_;
    CommandBuffer commands_;
    Fence fence_;
    DeviceHandle<VkSemaphore> acquired_, rendered_;
    std::uint64_t key_state_ = 0;  // which of poll()'s press keys were down at the last poll
    struct Functions;
    std::unique_ptr<Functions> fn_;
};

}  // namespace ts::gpu
