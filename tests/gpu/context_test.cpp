#include <gtest/gtest.h>

#include "gpu/physical_device.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu {
namespace {

using ContextTest = test_support::ValidatedTest;

TEST_F(ContextTest, ChoosesTheDefaultUsableDevice) {
    const PhysicalDeviceInfo& chosen = context_->device_info();
    EXPECT_TRUE(chosen.usable());
    EXPECT_FALSE(chosen.name.empty());
    EXPECT_GE(chosen.api_version, static_cast<std::uint32_t>(VK_API_VERSION_1_1));
    EXPECT_EQ(default_device_index(context_->all_devices()), chosen.index);
    EXPECT_TRUE(context_->validation_enabled());
}

TEST_F(ContextTest, MakesBuffersOfBothKinds) {
    const Buffer device_local = context_->create_buffer(1024);
    const Buffer host_visible = context_->create_buffer(1024, MemoryKind::host_visible);
    EXPECT_EQ(device_local.size(), 1024u);
    EXPECT_EQ(device_local.mapped(), nullptr);
    ASSERT_NE(host_visible.mapped(), nullptr);
    host_visible.mapped()[1023] = std::byte{7};  // the whole range is mapped and writable
    const Buffer empty = context_->create_buffer(0);
    EXPECT_EQ(empty.size(), 0u);
}

TEST_F(ContextTest, MovedBuffersAreDestroyedOnce) {
    Buffer a = context_->create_buffer(64, MemoryKind::host_visible);
    Buffer b = std::move(a);
    EXPECT_EQ(a.get(), VK_NULL_HANDLE);
    EXPECT_EQ(a.mapped(), nullptr);
    a = std::move(b);
    EXPECT_NE(a.get(), VK_NULL_HANDLE);
    // A double destroy or a leak shows up as a validation message in TearDown.
}

TEST(ContextSelection, AnOutOfRangeDeviceIsAnInputError) {
    ContextOptions options;
    options.validation = false;
    options.device_index = 99;
    EXPECT_THROW(Context{options}, InputError);
}

// The log really does catch mistakes: an invalid call (a buffer with no usage) must be reported.
TEST(ValidationLogTest, RecordsAMisuseOfTheApi) {
    auto log = std::make_shared<ValidationLog>(/*echo_to_stderr=*/false);
    ContextOptions options;
    options.validation = true;
    options.validation_log = log;
    Context context(options);
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 64;
    info.usage = 0;  // invalid: VUID-VkBufferCreateInfo-usage-requiredbitmask
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(context.vk_device(), &info, nullptr, &buffer);
    if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(context.vk_device(), buffer, nullptr);
    ASSERT_FALSE(log->empty());
    EXPECT_NE(log->messages().front().find("usage"), std::string::npos) << log->messages().front();
}

}  // namespace
}  // namespace ts::gpu
