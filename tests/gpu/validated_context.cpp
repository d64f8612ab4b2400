#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::test_support {

ValidatedTest::ValidatedTest() : log_(std::make_shared<ValidationLog>()) {
    ContextOptions options;
    options.validation = true;
    options.validation_log = log_;
    context_ = std::make_unique<Context>(options);
}

ValidatedTest::~ValidatedTest() = default;

void ValidatedTest::TearDown() {
    context_.reset();  // destruction is validated too
    EXPECT_TRUE(log_->empty()) << describe(*log_);
}

std::string describe(const ValidationLog& log) {
    std::string text;
    for (const auto& message : log.messages()) text += message + "\n";
    return text;
}

}  // namespace ts::gpu::test_support
