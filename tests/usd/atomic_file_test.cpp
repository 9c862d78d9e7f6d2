// The atomic writer under failure, for real: a disk that fills up halfway through a write
// (a small private tmpfs, tests/support/restricted_child.h), a folder the writer may not
// write into (as the user nobody, so that it holds when the tests run as root) and a
// writer by file name (an image library) that fails. Either way the error names the file
// and the cause, the previous file is intact and no temporary file is left. And the crash
// points a kill test aims at (crash_point.h).
#include "schema/error.h"
#include "schema/usd/atomic_file.h"
#include "schema/usd/crash_point.h"
#include "tests/support/open_temp_dir.h"
#include "tests/support/restricted_child.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace opal {
namespace {

using test::fileContents;
using test::OpenTempDir;

// In the child: a write that cannot succeed, over the previous file.
std::string failedRewrite(const std::filesystem::path& target, std::size_t bytes) {
    std::string message = "(no error)";
    try {
        writeFileAtomically(target, std::string(bytes, 'x'));
    } catch (const Error& e) {
        message = e.what();
    }
    return test::describeFailedRewrite(message, target);
}

TEST(AtomicFile, AFullDiskIsAClearErrorAndKeepsThePreviousFile) {
    const OpenTempDir dir;
    std::filesystem::create_directory(dir / "disk");
    const std::filesystem::path target = dir / "disk" / "layer.usda";
    const test::ChildReport r = test::onSmallDisk({dir / "disk", 64 * 1024}, [&] {
        writeFileAtomically(target, "previous");
        return failedRewrite(target, 256 * 1024);  // four times what the disk holds
    });
    ASSERT_TRUE(r.ran) << r.text;
    const test::FailedRewrite o = test::parseFailedRewrite(r.text);
    EXPECT_NE(o.message.find(target.string() + ": cannot write file"), std::string::npos) << o.message;
    EXPECT_NE(o.message.find(r.errorText), std::string::npos) << o.message;
    EXPECT_EQ(o.previous, "previous");
    EXPECT_EQ(o.files, "layer.usda") << "the temporary file is removed";
}

TEST(AtomicFile, AFolderItMayNotWriteIsAClearErrorAndKeepsThePreviousFile) {
    const OpenTempDir dir;
    std::filesystem::create_directory(dir / "locked");
    const std::filesystem::path target = dir / "locked" / "layer.usda";
    writeFileAtomically(target, "previous");
    ::chmod((dir / "locked").c_str(), 0555);
    const test::ChildReport r = test::unprivileged([&] { return failedRewrite(target, 10); });
    ASSERT_TRUE(r.ran) << r.text;
    const test::FailedRewrite o = test::parseFailedRewrite(r.text);
    EXPECT_NE(o.message.find(target.string() + ": cannot write file"), std::string::npos) << o.message;
    EXPECT_NE(o.message.find("Permission denied"), std::string::npos) << o.message;
    EXPECT_EQ(o.previous, "previous");
    EXPECT_EQ(o.files, "layer.usda");
}

// What an image library does: writes the file it is given by name.
void writeByName(const std::filesystem::path& target, const std::string& text) {
    writeAtomically(target, [&](const std::filesystem::path& temporary) {
        std::ofstream(temporary, std::ios::binary) << text;
    });
}

TEST(AtomicWriteByName, ReplacesTheTargetAndLeavesNoTemporary) {
    const OpenTempDir dir;
    writeByName(dir / "out.exr", "first");
    writeByName(dir / "out.exr", "second");
    EXPECT_EQ(fileContents(dir / "out.exr"), "second");
    EXPECT_EQ(test::folderListing(dir.path()), "out.exr");
}

TEST(AtomicWriteByName, TheTemporaryKeepsTheExtensionInTheSameFolder) {
    const OpenTempDir dir;
    std::filesystem::path seen;
    writeAtomically(dir / "beauty.png", [&](const std::filesystem::path& temporary) {
        seen = temporary;
        EXPECT_TRUE(std::filesystem::is_regular_file(temporary));
        EXPECT_EQ(std::filesystem::file_size(temporary), 0u);
    });
    EXPECT_EQ(seen.parent_path(), dir.path());
    EXPECT_EQ(seen.extension(), ".png");
    EXPECT_NE(seen.filename(), "beauty.png");
}

TEST(AtomicWriteByName, AWriterThatFailsHalfwayKeepsThePreviousFileAndSaysWhy) {
    const OpenTempDir dir;
    const std::filesystem::path target = dir / "out.exr";
    writeByName(target, "complete");
    try {
        writeAtomically(target, [](const std::filesystem::path& temporary) {
            std::ofstream(temporary) << "half-wri";
            throw std::runtime_error("bad pixels");
        });
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), target.string() + ": bad pixels");
    }
    EXPECT_EQ(fileContents(target), "complete");
    EXPECT_EQ(test::folderListing(dir.path()), "out.exr");
}

TEST(AtomicWriteByName, AFolderItMayNotWriteIsAClearErrorAndKeepsThePreviousFile) {
    const OpenTempDir dir;
    std::filesystem::create_directory(dir / "locked");
    const std::filesystem::path target = dir / "locked" / "out.exr";
    writeByName(target, "previous");
    ::chmod((dir / "locked").c_str(), 0555);
    const test::ChildReport r = test::unprivileged([&] {
        std::string message = "(no error)";
        bool called = false;
        try {
            writeAtomically(target, [&](const std::filesystem::path&) { called = true; });
        } catch (const Error& e) {
            message = e.what();
        }
        return test::describeFailedRewrite(message + (called ? " (the writer was called)" : ""), target);
    });
    ASSERT_TRUE(r.ran) << r.text;
    const test::FailedRewrite o = test::parseFailedRewrite(r.text);
    EXPECT_TRUE(o.message.starts_with(target.string() + ": cannot create the temporary file")) << o.message;
    EXPECT_NE(o.message.find("Permission denied"), std::string::npos) << o.message;
    EXPECT_EQ(o.message.find("the writer was called"), std::string::npos) << o.message;
    EXPECT_EQ(o.previous, "previous");
    EXPECT_EQ(o.files, "out.exr");
}

// Runs `point` in a child with OPAL_CRASH_AT=`wanted`; returns the signal that ended it.
int crashSignal(const char* wanted, const char* point) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::setenv(kCrashPointVariable, wanted, 1);
        crashPoint(point);
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

TEST(CrashPoint, KillsTheProcessAtTheNamedPointOnly) {
    EXPECT_EQ(crashSignal("usda:written", "usda:written"), SIGKILL);
    EXPECT_EQ(crashSignal("usda:written", "usda:renamed"), 0);
    EXPECT_EQ(crashSignal("", "usda:written"), 0);
}

// Killed after the rename: the new file is complete in place; before it, only a complete
// previous file and a temporary. Both ways of writing pass the same points.
void expectCrashPointsInOrder(const std::function<void(const std::filesystem::path&, const std::string&)>& write) {
    const OpenTempDir dir;
    const std::filesystem::path target = dir / "a.usda";
    write(target, "previous");
    for (const char* point : {"usda:created", "usda:written", "usda:renamed"}) {
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::setenv(kCrashPointVariable, point, 1);
            write(target, std::string("new ") + point);
            ::_exit(0);
        }
        int status = 0;
        ::waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << point;
        const bool renamed = std::string(point) == "usda:renamed";
        EXPECT_EQ(fileContents(target), renamed ? std::string("new ") + point : std::string("previous")) << point;
        write(target, "previous");
    }
}

TEST(CrashPoint, TheWriterReachesItsPointsInOrder) {
    expectCrashPointsInOrder([](const std::filesystem::path& target, const std::string& text) {
        writeFileAtomically(target, text);
    });
}

TEST(CrashPoint, TheWriterByNameReachesItsPointsInOrder) { expectCrashPointsInOrder(writeByName); }

}  // namespace
}  // namespace opal
