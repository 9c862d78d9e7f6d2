// Which files of a folder belong to an output stem (bake/asset_stem.h), and the lock that
// keeps two writers of one stem apart (bake/stem_lock.h).
#include "bake/asset_stem.h"
#include "bake/stem_lock.h"
#include "schema/error.h"
#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

namespace opal {
namespace {

TEST(AssetStem, NamesItsFilesBesideTheStem) {
    const AssetStem stem("/out/candle");
    EXPECT_EQ(stem.layer(), "/out/candle.usda");
    EXPECT_EQ(stem.sidecar(0x00000000000000ffull), "/out/candle.00000000000000ff.opal");
    EXPECT_EQ(stem.lockFile(), "/out/candle.lock");
}

TEST(AssetStem, TellsItsOwnSidecarsAndTemporariesFromAnotherStems) {
    const AssetStem stem("out/candle");
    for (const char* own : {"candle.opal", "candle.0123456789abcdef.opal"}) EXPECT_TRUE(stem.isSidecar(own)) << own;
    for (const char* other :
         {"candle.usda", "candle.lock", "candle.v2.0123456789abcdef.opal", "candle.v2.opal", "candles.opal",
          "candle.0123456789ABCDEF.opal", "candle.0123456789abcdef.0123456789abcdef.opal", "candle..opal", "x.opal"})
        EXPECT_FALSE(stem.isSidecar(other)) << other;
    for (const char* own : {"candle.usda.tmp-12-ab", "candle.opal.tmp-1-0", "candle.0123456789abcdef.opal.tmp-99-f"})
        EXPECT_TRUE(stem.isTemporary(own)) << own;
    for (const char* other : {"candle.usda", "candle.v2.usda.tmp-1-2", "candle.v2.0123456789abcdef.opal.tmp-1-2",
                              "bake.json.tmp-1-2", "candle.lock.tmp-1-2", "candle.exr.tmp-1-2"})
        EXPECT_FALSE(stem.isTemporary(other)) << other;
}

TEST(AssetStem, RemovesStaleTemporariesAndSupersededSidecarsOfItsOwnOnly) {
    const test::ScratchDir dir;
    for (const char* name : {"candle.usda", "candle.opal", "candle.1111111111111111.opal",
                             "candle.2222222222222222.opal", "candle.usda.tmp-5-a", "candle.2222222222222222.opal.tmp-5-b",
                             "candle.v2.usda", "candle.v2.3333333333333333.opal", "candle.v2.usda.tmp-5-c"})
        test::writeText(dir / name, name);
    const AssetStem stem(dir / "candle");
    std::vector<std::string> warnings;
    stem.removeStaleTemporaries(&warnings);
    EXPECT_EQ(dir.list(), (std::vector<std::string>{"candle.1111111111111111.opal", "candle.2222222222222222.opal",
                                                    "candle.opal", "candle.usda", "candle.v2.3333333333333333.opal",
                                                    "candle.v2.usda", "candle.v2.usda.tmp-5-c"}));
    stem.removeSidecarsExcept(0x2222222222222222ull, &warnings);
    EXPECT_EQ(dir.list(), (std::vector<std::string>{"candle.2222222222222222.opal", "candle.usda",
                                                    "candle.v2.3333333333333333.opal", "candle.v2.usda",
                                                    "candle.v2.usda.tmp-5-c"}));
    EXPECT_TRUE(warnings.empty());
}

TEST(StemLock, ASecondHolderIsRefusedWithTheFirstsPidAndTheLockGoesAway) {
    const test::ScratchDir dir;
    const AssetStem stem(dir / "candle");
    {
        const StemLock first(stem);
        EXPECT_TRUE(std::filesystem::exists(stem.lockFile()));
        // Another process: flock excludes open file descriptions, so a child is the honest
        // contender.
        int pipeFds[2];
        ASSERT_EQ(pipe(pipeFds), 0);
        const pid_t child = fork();
        if (child == 0) {
            std::string message = "(no error)";
            try {
                const StemLock second(stem);
            } catch (const Error& e) {
                message = e.what();
            }
            const ssize_t written = write(pipeFds[1], message.data(), message.size());
            _exit(written == ssize_t(message.size()) ? 0 : 1);
        }
        close(pipeFds[1]);
        std::string message;
        char buffer[512];
        for (ssize_t n; (n = read(pipeFds[0], buffer, sizeof buffer)) > 0;) message.append(buffer, std::size_t(n));
        close(pipeFds[0]);
        int status = 0;
        waitpid(child, &status, 0);
        EXPECT_NE(message.find(stem.lockFile().string()), std::string::npos) << message;
        EXPECT_NE(message.find("another opal-bake (pid " + std::to_string(getpid()) + ")"), std::string::npos)
            << message;
    }
    EXPECT_FALSE(std::filesystem::exists(stem.lockFile())) << "released locks leave no file";
    const StemLock again(stem);  // free again
}

TEST(StemLock, AMissingFolderIsAClearError) {
    const test::ScratchDir dir;
    try {
        const StemLock lock{AssetStem(dir / "missing" / "candle")};
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find((dir / "missing" / "candle.lock").string()), std::string::npos) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace opal
