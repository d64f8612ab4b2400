// Without any Vulkan driver, or without the Vulkan loader, making a Context must end in one
// clear line naming the package to install, not a crash. The probe runs in a child process whose loader is pointed at a driver
// manifest that does not exist (VK_ICD_FILENAMES for older loaders, VK_DRIVER_FILES for newer).
#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

struct ProbeResult {
    int exit_code = -1;
    std::string output;
};

ProbeResult run_probe(const std::string& environment) {
    const std::string command = environment + " " TS_GPU_CONTEXT_PROBE " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) return {};
    ProbeResult result;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), chunk.size(), pipe) != nullptr) result.output += chunk.data();
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

const std::string kNoDriver =
    "VK_ICD_FILENAMES=/nonexistent/terrashade_icd.json VK_DRIVER_FILES=/nonexistent/terrashade_icd.json";

TEST(NoVulkanDevice, ProbeWorksWithTheRealDriver) {
    // The control: the same probe succeeds when the driver is there, so the failure below is
    // caused by the missing driver and nothing else.
    const ProbeResult result = run_probe("");
    EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST(NoVulkanDevice, IsOneLineNamingThePackage) {
    for (const std::string validation : {"TERRASHADE_VALIDATION=0", "TERRASHADE_VALIDATION=1"}) {
        const ProbeResult result = run_probe(kNoDriver + " " + validation);
        EXPECT_EQ(result.exit_code, 2) << validation << ": " << result.output;
        EXPECT_NE(result.output.find("mesa-vulkan-drivers"), std::string::npos) << validation << ": " << result.output;
        // Ours is exactly one line, the last. With validation on, the loader's own complaints
        // come before it through the debug messenger ("terrashade: vulkan validation: ...").
        std::vector<std::string> lines;
        std::istringstream stream(result.output);
        for (std::string line; std::getline(stream, line);) lines.push_back(line);
        ASSERT_FALSE(lines.empty());
        EXPECT_EQ(lines.back().rfind("terrashade: vulkan: ", 0), 0u) << lines.back();
        for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
            EXPECT_EQ(lines[i].rfind("terrashade: vulkan validation: ", 0), 0u) << validation << ": " << lines[i];
        }
        if (validation == "TERRASHADE_VALIDATION=0") {
            EXPECT_EQ(lines.size(), 1u) << result.output;
        }
    }
}

// No loader at all: terrashade does not link libvulkan, it opens it when a Context is made;
// TERRASHADE_VULKAN_LIBRARY points that at a file that does not exist.
TEST(NoVulkanLoader, IsOneLineNamingThePackages) {
    const ProbeResult result = run_probe("TERRASHADE_VULKAN_LIBRARY=/nonexistent/libvulkan.so.1");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_EQ(result.output.rfind("terrashade: vulkan: cannot load the Vulkan loader", 0), 0u) << result.output;
    EXPECT_NE(result.output.find("libvulkan1"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("mesa-vulkan-drivers"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find('\n'), result.output.size() - 1) << "expected one line: " << result.output;
}

}  // namespace
