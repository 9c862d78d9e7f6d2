// opal-bake --farm slurm through a real single-node Slurm cluster (scripts/slurm-cluster,
// started by the ctest fixture `slurm`; SLURM_CONF points at it): the asset of 4 shards is
// byte-identical to the plain bake's, and its --json report has every task's time and peak
// memory; a task killed mid-way is run again and the asset is still identical; a task
// failing twice fails the bake naming its log, and leaves nothing of the bake in the queue
// (the stages behind it cancelled, not pending forever). A batch on Slurm bakes the plain
// batch's bytes. A second user's start and stop of scripts/slurm-cluster leave the cluster.
#include "tests/bake/farm_test_support.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace opal {
namespace {

using namespace std::chrono_literals;
using test::expectSameAsset;
using test::PlainBake;
using test::ScratchDir;
using test::with;

// Job ids opal-bake printed ("STAGE ID" a line), in stage order.
std::vector<std::string> jobIds(const std::string& out) {
    std::istringstream lines(out);
    std::vector<std::string> ids;
    std::string stage, id;
    while (lines >> stage >> id)
        ids.push_back(id);
    return ids;
}

// squeue's lines for these jobs (array job id, state).
std::string queued(const std::vector<std::string>& ids) {
    const test::RunResult q = test::run({"/usr/bin/squeue", "-h", "-o", "%F %T"}, 30s);
    EXPECT_EQ(q.exitCode, 0) << q.err;
    std::istringstream lines(q.out);
    std::string line, found;
    while (std::getline(lines, line))
        for (const std::string& id : ids)
            if (line.rfind(id + " ", 0) == 0) found += line + "\n";
    return found;
}

TEST(SlurmFarm, FourShardsThroughSlurmAreByteIdenticalToThePlainBake) {
    ASSERT_NE(std::getenv("SLURM_CONF"), nullptr) << "run through ctest: its fixture starts the cluster";
    const PlainBake plain;
    const ScratchDir farm;
    const std::filesystem::path report = plain.dir / "farm.json";  // each task's time and memory under Slurm
    const test::RunResult r = test::bakeWith(with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm",
                                                                       "slurm", "--shards", "4", "--wait", "--json",
                                                                       report.string()}));
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(jobIds(r.out).size(), 5u) << r.out;  // prepare, rows, columns, keep, merge
    expectSameAsset(plain, farm, "slurm, 4 shards");
    test::expectFarmReport(plain, report, 4);
}

TEST(SlurmFarm, ATaskKilledMidWayIsRunAgainAndTheAssetIsUnchanged) {
    const PlainBake plain;
    const ScratchDir farm;
    const test::RunResult r = test::bakeWith(
        with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm", "slurm", "--shards", "4", "--wait"}),
        {"OPAL_CRASH_AT=farm:rows-2:attempt-1"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    expectSameAsset(plain, farm, "slurm, rows 2 killed once");
}

TEST(SlurmFarm, ATaskFailingTwiceFailsTheBakeNamingItsLogAndLeavesNothingQueued) {
    const ScratchDir farm;
    const test::RunResult r = test::bakeWith(
        with(test::kFarmOptions, {"-o", (farm / "candle").string(), "--farm", "slurm", "--shards", "4", "--wait"}),
        {"OPAL_CRASH_AT=farm:columns-3"});
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    const std::string log = (farm / "candle.farm" / "logs" / "columns-3.log").string();
    EXPECT_NE(
        r.err.find("farm task columns 3 failed twice (killed by signal 9, then killed by signal 9); its log: " + log),
        std::string::npos)
        << r.err;
    EXPECT_TRUE(std::filesystem::exists(log));
    EXPECT_FALSE(std::filesystem::exists(farm / "candle.usda"));
    const std::vector<std::string> ids = jobIds(r.out);
    ASSERT_EQ(ids.size(), 5u) << r.out;
    // The keep and merge arrays are cancelled at once; give slurmctld a moment to drop
    // the columns array's last tasks.
    std::string left;
    for (int i = 0; i < 40 && !(left = queued(ids)).empty(); ++i)
        std::this_thread::sleep_for(250ms);
    EXPECT_EQ(left, "") << "jobs of the failed bake are still queued";
}

// `opal-bake batch --farm slurm`: every asset's farm bake submitted at once, the plain
// batch's bytes, the failure (an input that is not there) retried once and listed first.
TEST(SlurmFarm, ABatchOnSlurmBakesThePlainBatchsBytesAndReportsTheFailureFirst) {
    const std::string manifest = R"({"assets": [
  {"input": "builtin:wick", "output": "out/wick", "args": ["--samples", "256"]},
  {"input": "missing.obj", "output": "out/missing"},
  {"input": "builtin:candle", "output": "out/candle", "args": ["--samples", "256", "--level", "1"]}
]})";
    const ScratchDir plain, farm;
    test::writeText(plain / "batch.json", manifest);
    test::writeText(farm / "batch.json", manifest);
    const auto runBatch = [](const ScratchDir& dir, std::vector<std::string> extra) {
        std::vector<std::string> args = {OPAL_BAKE_EXE, "batch", (dir / "batch.json").string(), "--json",
                                         (dir / "report.json").string()};
        args.insert(args.end(), extra.begin(), extra.end());
        return test::run(args, std::chrono::seconds(300));
    };
    ASSERT_EQ(runBatch(plain, {}).exitCode, 1);
    const test::RunResult r = runBatch(farm, {"--farm", "slurm", "--shards", "2"});
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    const nlohmann::json report = test::readJson(farm / "report.json");
    ASSERT_TRUE(report.is_object()) << r.err;
    std::vector<std::string> statuses;
    for (const auto& asset : report["assets"]) statuses.push_back(asset["status"].get<std::string>());
    EXPECT_EQ(statuses, (std::vector<std::string>{"baked", "failed", "baked"}));
    EXPECT_EQ(report["assets"][1]["attempts"], 2);
    EXPECT_LT(r.out.find("failed"), r.out.find("baked")) << r.out;
    for (const char* stem : {"wick", "candle"}) {
        const std::string sidecar = test::sidecarNamedBy(farm / "out" / (std::string(stem) + ".usda"));
        for (const std::string& file : {std::string(stem) + ".usda", sidecar})
            EXPECT_TRUE(test::readBytes(farm / "out" / file) == test::readBytes(plain / "out" / file))
                << file << ": the Slurm batch's differs from the plain batch's";
        // Its log holds what opal-bake --farm slurm printed: the job ids of its five stages.
        EXPECT_EQ(jobIds(test::readBytes(farm / "out" / (std::string(stem) + ".batch.log"))).size(), 5u) << stem;
    }
}

std::string pidIn(const std::filesystem::path& file) {
    std::string text = test::readBytes(file);
    return text.substr(0, text.find_last_not_of("\n") + 1);
}

std::string jobState(const std::string& id) {
    return test::run({"/usr/bin/squeue", "-h", "-j", id, "-o", "%T"}, std::chrono::seconds(30)).out;
}

// scripts/slurm-cluster run by a second user (another build's tests) while this one's job
// runs: its start finds the cluster up and leaves it, and its stop leaves it to this user.
TEST(SlurmCluster, ASecondUsersStartAndStopLeaveTheRunningClusterAndItsJobAlone) {
    const char* dir = std::getenv("OPAL_SLURM_DIR");
    ASSERT_NE(dir, nullptr) << "run through ctest: its fixture starts the cluster";
    const std::filesystem::path folder = dir;
    const std::string controller = pidIn(folder / "slurmctld.pid"), node = pidIn(folder / "slurmd.pid");
    const test::RunResult submitted =
        test::run({"/usr/bin/sbatch", "--parsable", "--job-name=opal-cluster-test", "--wrap=sleep 60"}, 30s);
    ASSERT_EQ(submitted.exitCode, 0) << submitted.err;
    const std::string id = submitted.out.substr(0, submitted.out.find_first_of(";\n"));
    for (int i = 0; i < 120 && jobState(id) != "RUNNING\n"; ++i) std::this_thread::sleep_for(250ms);
    ASSERT_EQ(jobState(id), "RUNNING\n");

    const std::string script = std::string(OPAL_SOURCE_DIR) + "/scripts/slurm-cluster";
    const test::RunResult second = test::run({script, "start"}, 90s, {"OPAL_SLURM_USER=second-user"});
    EXPECT_EQ(second.exitCode, 0) << second.err;
    EXPECT_NE(second.out.find("slurm-cluster: running"), std::string::npos) << second.out << second.err;
    const test::RunResult stopped = test::run({script, "stop"}, 90s, {"OPAL_SLURM_USER=second-user"});
    EXPECT_EQ(stopped.exitCode, 0) << stopped.err;
    EXPECT_NE(stopped.out.find("left running"), std::string::npos) << stopped.out;

    EXPECT_EQ(pidIn(folder / "slurmctld.pid"), controller) << "slurmctld was restarted";
    EXPECT_EQ(pidIn(folder / "slurmd.pid"), node) << "slurmd was restarted";
    EXPECT_EQ(jobState(id), "RUNNING\n") << "the running job was lost";
    test::run({"/usr/bin/scancel", id}, 30s);
}

}  // namespace
}  // namespace opal
