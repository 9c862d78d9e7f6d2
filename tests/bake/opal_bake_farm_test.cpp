// opal-bake --farm local: the staged, file-based bake (bake/farm/) against the plain bake
// of the same input and options, byte for byte, for 1, 3 and 7 shards; a task killed
// once is run again; a task failing twice fails the bake naming its log, and a second run
// resumes from the tasks already done. Every run is a real opal-bake process.
#include "bake/farm/farm_stage.h"
#include "bake/farm/task_file.h"
#include "schema/asset/asset_layer.h"
#include "schema/asset/xxhash64.h"
#include "tests/bake/farm_test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace opal {
namespace {

using namespace std::chrono_literals;
using test::expectSameAsset;
using test::PlainBake;
using test::ScratchDir;
using test::with;

// XXH64 over the transfer matrices (offsets, columns, values, value steps) of
// builtin:candle at kFarmOptions as the plain bake wrote it before the bake was cut into
// stages: the farm must keep the exact same coefficients, not only agree with itself.
// Taken again (one value on every processor) when opal-bake moved to glibc's baseline math
// (bake/tool/baseline_math.h); the value before was this machine's FMA variants'. Taken
// again when step 2's default energy went from 0.99995 to 0.99998 (bake/transfer_builder.h).
constexpr std::uint64_t kPlainTransferDigest = 0x29fc516aab172b05ull;

std::uint64_t transferDigest(const std::filesystem::path& usda) {
    const TranslucentAsset asset = readAsset(usda);
    Xxh64 hash;
    const auto add = [&](const auto& values) { hash.update(std::as_bytes(std::span(values))); };
    for (const SparseMatrix& m : asset.transfer.perBasis) {
        add(m.rowOffsets);
        add(m.columns);
        add(m.values);
    }
    add(asset.transfer.valueSteps);
    return hash.digest();
}

TEST(OpalBakeFarm, LocalFarmIsByteIdenticalToThePlainBakeFor1_3And7Shards) {
    const PlainBake plain;
    EXPECT_EQ(transferDigest(plain.dir / "candle.usda"), kPlainTransferDigest) << "the plain bake's transfer changed";
    for (const char* shards : {"1", "3", "7"}) {
        const ScratchDir farm;
        const std::filesystem::path report = plain.dir / ("farm" + std::string(shards) + ".json");
        const test::RunResult r = test::bakeWith(with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm",
                                                                           "local", "--shards", shards, "--json",
                                                                           report.string()}));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        expectSameAsset(plain, farm, std::string(shards) + " shards");  // and no candle.farm left
        test::expectFarmReport(plain, report, std::stoi(shards));
    }
}

TEST(OpalBakeFarm, ATaskKilledOnceRunsAgainAndTheAssetIsUnchanged) {
    const PlainBake plain;
    const ScratchDir farm;
    const test::RunResult r = test::bakeWith(
        with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm", "local", "--shards", "3", "--quiet"}),
        {"OPAL_CRASH_AT=farm:columns-1:attempt-1"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    expectSameAsset(plain, farm, "after a killed columns task");
}

TEST(OpalBakeFarm, ATaskFailingTwiceFailsTheBakeNamingItsLogAndARerunResumes) {
    const PlainBake plain;
    const ScratchDir farm;
    const std::vector<std::string> args =
        with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm", "local", "--shards", "3"});
    const test::RunResult failed = test::bakeWith(args, {"OPAL_CRASH_AT=farm:columns-1"});
    EXPECT_EQ(failed.exitCode, 1) << failed.err;
    const std::string log = (farm / "candle.farm" / "logs" / "columns-1.log").string();
    EXPECT_NE(failed.err.find(
                  "farm task columns 1 failed twice (killed by signal 9, then killed by signal 9); its log: " + log),
              std::string::npos)
        << failed.err;
    EXPECT_FALSE(std::filesystem::exists(farm / "candle.usda"));
    EXPECT_TRUE(std::filesystem::exists(farm / "candle.farm" / "rows-0000.task"));

    // The rows are done: run again with rows 0 set to crash; it is not run, so the bake
    // completes, from the same files, to the same bytes.
    const test::RunResult resumed = test::bakeWith(args, {"OPAL_CRASH_AT=farm:rows-0"});
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    expectSameAsset(plain, farm, "resumed");
}

TEST(OpalBakeFarm, ABakeThePrepareTaskWouldRefuseFailsBeforeAnythingIsSetUp) {
    const ScratchDir farm;
    const test::RunResult samples = test::bakeWith(
        {"builtin:candle", "--samples", "1000", "-o", (farm / "candle").string(), "--farm", "local"});
    EXPECT_EQ(samples.exitCode, 1) << samples.err;
    EXPECT_NE(samples.err.find("1000"), std::string::npos) << samples.err;
    const test::RunResult input = test::bakeWith(
        {(farm / "missing.obj").string(), "-o", (farm / "candle").string(), "--farm", "slurm", "--shards", "2"});
    EXPECT_EQ(input.exitCode, 1) << input.err;
    EXPECT_NE(input.err.find((farm / "missing.obj").string() + ": no such input file"), std::string::npos) << input.err;
    // The merge would write the report only after the asset: refused before anything runs.
    const std::string report = (farm / "nowhere" / "report.json").string();
    const test::RunResult json = test::bakeWith(
        with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm", "local", "--json", report}));
    EXPECT_EQ(json.exitCode, 1) << json.err;
    EXPECT_NE(json.err.find(report + ": --json: its folder does not exist"), std::string::npos) << json.err;
    EXPECT_EQ(farm.list(), std::vector<std::string>{});  // no candle.farm, no lock, nothing submitted
}

TEST(OpalBakeFarm, ADamagedTaskFileIsRefusedNamingTheFileAndSection) {
    const ScratchDir dir;
    const std::filesystem::path file = dir / "rows-0000.task";
    const std::vector<std::string> sections = {"first section", std::string(100, 'x')};
    writeTaskFile(file, sections);
    EXPECT_TRUE(isCompleteTaskFile(file));
    std::string bytes = test::readBytes(file);
    bytes[bytes.size() - 10] ^= 1;  // inside section 1
    test::writeText(file, bytes);
    EXPECT_FALSE(isCompleteTaskFile(file));
    const TaskFile damaged(file);
    EXPECT_NO_THROW((void)damaged.section(0));
    try {
        (void)damaged.section(1);
        FAIL() << "a damaged section was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string() + ": section 1: checksum mismatch"), std::string::npos)
            << e.what();
    }
    test::writeText(file, bytes.substr(0, bytes.size() - 1));
    try {
        (void)TaskFile(file);
        FAIL() << "a truncated task file was opened";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string() + ": section 1 of 100 bytes runs past the end"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace opal
