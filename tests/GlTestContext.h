#pragma once
// GoogleTest fixture for gl-labelled tests: one headless EGL context per test suite, made current
// before each test. Derive from GlTest (and ::testing::WithParamInterface<T> for parameters).

#include <renderer/HeadlessContext.h>

#include <gtest/gtest.h>

namespace sdfwb::testing {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto created = renderer::HeadlessContext::create();
        ASSERT_TRUE(created.hasValue()) << created.error().message;
        s_context = std::move(created.value()).release();
    }
    static void TearDownTestSuite() {
        delete s_context;
        s_context = nullptr;
    }
    void SetUp() override { ASSERT_TRUE(s_context && s_context->makeCurrent()); }
    static const renderer::HeadlessContext& context() { return *s_context; }

private:
    static inline renderer::HeadlessContext* s_context = nullptr;
};

} // namespace sdfwb::testing
