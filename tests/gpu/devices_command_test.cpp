// `terrashade devices`: lists the devices, marks the default, runs the self-test, and fails
// with one line naming the package when there is no driver.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

struct CommandRun {
    int exit_code = -1;
    std::string out;  // stdout and stderr together
};

CommandRun terrashade(const std::string& environment, const std::string& arguments) {
    const std::string command = environment + " " TS_BIN " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) return {};
    CommandRun run;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), chunk.size(), pipe) != nullptr) run.out += chunk.data();
    const int status = pclose(pipe);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(DevicesCommand, ListsDevicesAndMarksTheDefault) {
    const CommandRun run = terrashade("TERRASHADE_VALIDATION=1", "devices");
    EXPECT_EQ(run.exit_code, 0) << run.out;
    EXPECT_TRUE(contains(run.out, "index")) << run.out;
    EXPECT_TRUE(contains(run.out, "(default)")) << run.out;
    EXPECT_FALSE(contains(run.out, "validation:")) << run.out;
}

TEST(DevicesCommand, SelfTestPassesWithValidation) {
    const CommandRun run = terrashade("TERRASHADE_VALIDATION=1", "devices --test --device 0");
    EXPECT_EQ(run.exit_code, 0) << run.out;
    EXPECT_TRUE(contains(run.out, "self-test passed")) << run.out;
    EXPECT_TRUE(contains(run.out, "validation on")) << run.out;
    EXPECT_FALSE(contains(run.out, "validation:")) << run.out;  // no message from the layer
}

TEST(DevicesCommand, UnknownDeviceIsBadInput) {
    const CommandRun run = terrashade("", "devices --test --device 99");
    EXPECT_EQ(run.exit_code, 2) << run.out;
    EXPECT_TRUE(contains(run.out, "--device 99")) << run.out;
}

TEST(DevicesCommand, NoDriverIsOneLineNamingThePackage) {
    const CommandRun run = terrashade("VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json",
                               "devices");
    EXPECT_EQ(run.exit_code, 2) << run.out;
    EXPECT_TRUE(contains(run.out, "mesa-vulkan-drivers")) << run.out;
    EXPECT_EQ(run.out.find('\n'), run.out.size() - 1) << "expected one line: " << run.out;
}

TEST(DevicesCommand, NoLoaderIsOneLineNamingThePackages) {
    const CommandRun run = terrashade("TERRASHADE_VULKAN_LIBRARY=/nonexistent/libvulkan.so.1", "devices");
    EXPECT_EQ(run.exit_code, 2) << run.out;
    EXPECT_TRUE(contains(run.out, "libvulkan1")) << run.out;
    EXPECT_EQ(run.out.find('\n'), run.out.size() - 1) << "expected one line: " << run.out;
}

}  // namespace
