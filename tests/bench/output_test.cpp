// The benchmarks' result files under failure, for real: a disk that fills up (a small
// private tmpfs) and a folder the writer may not write into (as the user nobody, so that
// it holds when the tests run as root). The error names the file and the cause, and the
// previous file is intact.
#include "bench/output.h"
#include "tests/support/open_temp_dir.h"
#include "tests/support/restricted_child.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace opal::bench {
namespace {

using test::fileContents;
using test::folderListing;
using test::OpenTempDir;

// "<error message>\n<previous contents>\n<folder listing>", observed in the child.
std::string failedRewrite(const std::filesystem::path& target, std::size_t bytes) {
    std::string message = "(no error)";
    try {
        writeTextAtomically(target, std::string(bytes, 'x'));
    } catch (const std::runtime_error& e) {
        message = e.what();
    }
    return test::describeFailedRewrite(message, target);
}

void expectReport(const test::ChildReport& r, const std::filesystem::path& target, const std::string& cause) {
    ASSERT_TRUE(r.ran) << r.text;
    const test::FailedRewrite o = test::parseFailedRewrite(r.text);
    EXPECT_NE(o.message.find(target.string()), std::string::npos) << o.message;
    EXPECT_NE(o.message.find(cause), std::string::npos) << o.message;
    EXPECT_EQ(o.previous, "previous");
    EXPECT_EQ(o.files, target.filename().string()) << "the temporary file is removed";
}

TEST(BenchOutput, AFullDiskIsAClearErrorAndKeepsThePreviousFile) {
    const OpenTempDir dir;
    std::filesystem::create_directory(dir / "disk");
    const std::filesystem::path target = dir / "disk" / "results.json";
    const test::ChildReport r = test::onSmallDisk({dir / "disk", 64 * 1024}, [&] {
        writeTextAtomically(target, "previous");
        return failedRewrite(target, 256 * 1024);
    });
    expectReport(r, target, r.errorText);
}

TEST(BenchOutput, AFolderItMayNotWriteIsAClearErrorAndKeepsThePreviousFile) {
    const OpenTempDir dir;
    std::filesystem::create_directory(dir / "locked");
    const std::filesystem::path target = dir / "locked" / "results.json";
    writeTextAtomically(target, "previous");
    ::chmod((dir / "locked").c_str(), 0555);
    expectReport(test::unprivileged([&] { return failedRewrite(target, 10); }), target, "Permission denied");
}

TEST(BenchOutput, AWriterThatFailsKeepsThePreviousFileAndSaysWhy) {
    const OpenTempDir dir;
    const std::filesystem::path target = dir / "plot.png";
    writeTextAtomically(target, "previous");
    try {
        writeFileAtomically(target, [](const std::filesystem::path&) -> bool { throw std::runtime_error("bad pixels"); });
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad pixels"), std::string::npos) << e.what();
    }
    EXPECT_EQ(fileContents(target), "previous");
    EXPECT_EQ(folderListing(dir.path()), "plot.png");
}

}  // namespace
}  // namespace opal::bench
