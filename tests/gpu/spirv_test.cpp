#include <stdexcept>

#include <gtest/gtest.h>

#include "gpu/spirv.hpp"

namespace ts::gpu {
namespace {

constexpr std::uint32_t kSpirvMagic = 0x07230203;

TEST(Spirv, EmbeddedShadersStartWithTheSpirvMagicNumber) {
    ASSERT_FALSE(embedded_shaders().empty());
    for (const SpirvBlob* blob : embedded_shaders()) {
        ASSERT_GE(blob->words.size(), 5u) << blob->name;  // the SPIR-V header is 5 words
        EXPECT_EQ(blob->words[0], kSpirvMagic) << blob->name;
    }
}

TEST(Spirv, FindsAShaderByNameWithOrWithoutExtension) {
    const auto with = spirv("selftest_saxpy.comp");
    const auto without = spirv("selftest_saxpy");
    EXPECT_EQ(with.data(), without.data());
    EXPECT_EQ(with[0], kSpirvMagic);
}

TEST(Spirv, UnknownNameThrowsNamingIt) {
    try {
        spirv("no_such_shader");
        FAIL() << "expected std::out_of_range";
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_shader.comp"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace ts::gpu
