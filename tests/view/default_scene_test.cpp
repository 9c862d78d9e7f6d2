// With no argument opal-view opens the candle of scripts/run-main, and says to run it when
// the candle is not there.
#include "examples/opal-view/core/default_scene.h"
#include "schema/error.h"
#include "tests/scene/scene_test_files.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace opal::view {
namespace {

TEST(DefaultScene, IsTheCandleUnderTheOutputFolder) {
    const test::SceneDir dir;
    const std::filesystem::path scene = dir.write("out/candle/candlelight.usda", "#usda 1.0\n");
    ::setenv("OPAL_OUT_DIR", (dir / "out").c_str(), 1);
    EXPECT_EQ(defaultScene(dir / "checkout/build/bin/opal-view"), scene);
    ::unsetenv("OPAL_OUT_DIR");
}

TEST(DefaultScene, MissingSaysToRunTheMainJob) {
    const test::SceneDir dir;
    ::setenv("OPAL_OUT_DIR", (dir / "out").c_str(), 1);
    try {
        defaultScene(dir / "checkout/build/bin/opal-view");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("run scripts/run-main first"), std::string::npos) << message;
        EXPECT_NE(message.find((dir / "out/candle/candlelight.usda").string()), std::string::npos) << message;
    }
    ::unsetenv("OPAL_OUT_DIR");
}

}  // namespace
}  // namespace opal::view
