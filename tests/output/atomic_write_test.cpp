#include "delegate/output/atomic_write.h"

#include "color_test_support.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace opal {
namespace {

using test::TempDir;

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const std::filesystem::path& file, const std::string& text) {
    writeAtomically(
        file, [&](const std::filesystem::path& temporary) { std::ofstream(temporary) << text; });
}

TEST(AtomicWrite, ReplacesTheTargetAndLeavesNoTemporary) {
    TempDir dir;
    writeText(dir / "out.exr", "first");
    writeText(dir / "out.exr", "second");
    EXPECT_EQ(contents(dir / "out.exr"), "second");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});
}

TEST(AtomicWrite, TemporaryKeepsTheExtensionInTheSameDirectory) {
    TempDir dir;
    std::filesystem::path seen;
    writeAtomically(dir / "beauty.png", [&](const std::filesystem::path& temporary) {
        seen = temporary;
        EXPECT_TRUE(std::filesystem::exists(temporary));
    });
    EXPECT_EQ(seen.parent_path(), dir.path());
    EXPECT_EQ(seen.extension(), ".png");
}

TEST(AtomicWrite, FailureHalfwayKeepsThePreviousFile) {
    TempDir dir;
    writeText(dir / "out.exr", "complete");
    try {
        writeAtomically(dir / "out.exr", [](const std::filesystem::path& temporary) {
            std::ofstream(temporary) << "half-wri";
            throw Error("disk full");
        });
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "out.exr").string() + ": disk full");
    }
    EXPECT_EQ(contents(dir / "out.exr"), "complete");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});
}

}  // namespace
}  // namespace opal
