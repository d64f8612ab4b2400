// Device choice on made-up device lists: the machine has one device, the rule is for all.
#include <vector>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "gpu/physical_device.hpp"

namespace ts::gpu {
namespace {

PhysicalDeviceInfo fake(std::uint32_t index, VkPhysicalDeviceType type, std::string unusable = "") {
    PhysicalDeviceInfo info;
    info.index = index;
    info.name = "device " + std::to_string(index);
    info.type = type;
    info.api_version = VK_API_VERSION_1_1;
    info.compute_queue_family = 0;
    info.unusable_reason = std::move(unusable);
    return info;
}

TEST(DeviceChoice, PrefersDiscreteThenIntegratedThenVirtualThenCpu) {
    std::vector<PhysicalDeviceInfo> devices = {
        fake(0, VK_PHYSICAL_DEVICE_TYPE_CPU), fake(1, VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU),
        fake(2, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU), fake(3, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU)};
    EXPECT_EQ(default_device_index(devices), 3u);
    devices.pop_back();
    EXPECT_EQ(default_device_index(devices), 2u);
    devices.pop_back();
    EXPECT_EQ(default_device_index(devices), 1u);
    devices.pop_back();
    EXPECT_EQ(default_device_index(devices), 0u);
}

TEST(DeviceChoice, TakesTheFirstOfEqualTypes) {
    const std::vector<PhysicalDeviceInfo> devices = {fake(0, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
                                                     fake(1, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU)};
    EXPECT_EQ(default_device_index(devices), 0u);
}

TEST(DeviceChoice, SkipsUnusableDevices) {
    const std::vector<PhysicalDeviceInfo> devices = {
        fake(0, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "has no compute queue"), fake(1, VK_PHYSICAL_DEVICE_TYPE_CPU)};
    EXPECT_EQ(default_device_index(devices), 1u);
    EXPECT_EQ(choose_device(devices, std::nullopt).index, 1u);
}

TEST(DeviceChoice, HonoursARequestedIndex) {
    const std::vector<PhysicalDeviceInfo> devices = {fake(0, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
                                                     fake(1, VK_PHYSICAL_DEVICE_TYPE_CPU)};
    EXPECT_EQ(choose_device(devices, 1u).index, 1u);
}

TEST(DeviceChoice, RejectsAnOutOfRangeOrUnusableRequest) {
    const std::vector<PhysicalDeviceInfo> devices = {fake(0, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "has no compute queue"),
                                                     fake(1, VK_PHYSICAL_DEVICE_TYPE_CPU)};
    EXPECT_THROW(choose_device(devices, 2u), InputError);
    EXPECT_THROW(choose_device(devices, 0u), InputError);
}

TEST(DeviceChoice, NoUsableDeviceNamesThePackageToInstall) {
    const std::vector<PhysicalDeviceInfo> none;
    const std::vector<PhysicalDeviceInfo> unusable = {
        fake(0, VK_PHYSICAL_DEVICE_TYPE_CPU, "supports only Vulkan 1.0.0, needs 1.1")};
    for (const auto& devices : {none, unusable}) {
        try {
            choose_device(devices, std::nullopt);
            FAIL() << "expected ts::InputError";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("mesa-vulkan-drivers"), std::string::npos) << e.what();
        }
    }
}

// --device auto: a GPU of any kind takes the Vulkan path; a CPU implementation (lavapipe) or
// nothing usable takes the CPU path, and the reason says which.
TEST(DeviceChoice, AutoTakesAGpuAndLeavesCpuImplementationsForTheCpuPath) {
    for (VkPhysicalDeviceType type : {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                      VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU}) {
        const std::vector<PhysicalDeviceInfo> devices = {fake(0, VK_PHYSICAL_DEVICE_TYPE_CPU), fake(1, type)};
        const AutoPath p = choose_auto_path(devices);
        ASSERT_TRUE(p.device.has_value()) << p.reason;
        EXPECT_EQ(*p.device, 1u);
        EXPECT_NE(p.reason.find("the Vulkan path"), std::string::npos) << p.reason;
    }
    const std::vector<PhysicalDeviceInfo> lavapipe = {fake(0, VK_PHYSICAL_DEVICE_TYPE_CPU)};
    const AutoPath cpu = choose_auto_path(lavapipe);
    EXPECT_FALSE(cpu.device.has_value());
    EXPECT_NE(cpu.reason.find("the CPU path"), std::string::npos) << cpu.reason;
    EXPECT_NE(cpu.reason.find("device 0"), std::string::npos) << cpu.reason;  // names the device
    const std::vector<PhysicalDeviceInfo> broken_gpu = {
        fake(0, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "has no compute queue"), fake(1, VK_PHYSICAL_DEVICE_TYPE_CPU)};
    EXPECT_FALSE(choose_auto_path(broken_gpu).device.has_value());
    EXPECT_FALSE(choose_auto_path({}).device.has_value());
    EXPECT_NE(choose_auto_path({}).reason.find("the CPU path"), std::string::npos);
}

}  // namespace
}  // namespace ts::gpu
