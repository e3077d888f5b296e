// GlTest: a GoogleTest fixture with one headless GL 4.5 core debug context per test suite. Without
// GL the tests skip, or fail when VIZ_REQUIRE_GL=1 (CI). Each test must leave no
// GL_DEBUG_TYPE_ERROR message.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "gl/debug_output.h"
#include "gl/gl_error.h"
#include "platform/context_egl.h"

namespace viz::gl {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        try {
            context() = HeadlessContext::create(/*debug=*/true);
            installDebugOutput();
        } catch (const GlUnavailable& e) {
            unavailableReason() = e.what();
        }
    }
    static void TearDownTestSuite() { context().reset(); }

    void SetUp() override {
        if (!context()) {
            const char* require = std::getenv("VIZ_REQUIRE_GL");
            if (require != nullptr && std::string(require) == "1") {
                FAIL() << "VIZ_REQUIRE_GL=1 but: " << unavailableReason();
            }
            GTEST_SKIP() << unavailableReason();
        }
        resetDebugErrorCount();
    }
    void TearDown() override {
        if (context()) {
            EXPECT_EQ(debugErrorCount(), 0) << "GL_DEBUG_TYPE_ERROR messages during the test";
        }
    }

    // Function-local statics keep the header usable from several test files of one executable.
    static std::unique_ptr<HeadlessContext>& context() {
        static std::unique_ptr<HeadlessContext> sContext;
        return sContext;
    }
    static std::string& unavailableReason() {
        static std::string sReason;
        return sReason;
    }
};

}  // namespace viz::gl
