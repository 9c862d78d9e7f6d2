// The opal-bake executable as a pipeline sees it: exit codes (0 done, 1 error, 2 bad
// arguments, 130/143 interrupted), what it writes and what it leaves alone, the JSON
// report, progress output, and byte-identical repeat bakes. Every run is a real child
// process (posix_spawn) with stderr on a pipe, bounded by a deadline.
#include "bake/bake_pipeline.h"
#include "schema/asset/asset_layer.h"
#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <sstream>
#include <filesystem>
#include <string>
#include <vector>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for opal-test-bake"
#endif

namespace opal {
namespace {

using namespace std::chrono_literals;
using test::ScratchDir;

// A small, quick bake: the built-in candle at 256 samples (1 chart of 16 x 16).
const std::vector<std::string> kSmall = {"--samples", "256", "--level", "1", "--env-res", "8", "--env-terms", "32"};

test::RunResult bake(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {OPAL_BAKE_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    test::RunResult r = test::run(argv, 180s);
    EXPECT_FALSE(r.timedOut) << test::joined(argv) << "\nstderr:\n" << r.err;
    return r;
}

using test::with;

// ---- determinism --------------------------------------------------------------------

TEST(OpalBakeCli, TwoBakesOfTheSameInputAreByteIdentical) {
    const ScratchDir one, two;
    // 2048 samples: 2 charts, so step 2's per-chart transforms and parallel reductions run.
    const std::vector<std::string> args = {"builtin:candle", "--samples", "2048", "--level", "1",
                                           "--env-res",      "16",        "--quiet"};
    const test::RunResult a = bake(with(args, {"-o", (one / "candle").string()}));
    const test::RunResult b = bake(with(args, {"-o", (two / "candle").string()}));
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    const std::string sidecar = test::sidecarNamedBy(one / "candle.usda");
    EXPECT_EQ(sidecar, test::sidecarNamedBy(two / "candle.usda"));
    EXPECT_EQ(one.list(), (std::vector<std::string>{sidecar, "candle.usda"}));
    for (const std::string& file : {std::string("candle.usda"), sidecar}) {
        const std::string x = test::readBytes(one / file), y = test::readBytes(two / file);
        EXPECT_GT(x.size(), 1000u) << file;
        EXPECT_TRUE(x == y) << file << " differs between two identical bakes";
    }
    // ... and the result is a valid asset.
    EXPECT_EQ(readAsset(one / "candle.usda").samples.size(), 2048u);
}

// ---- malformed input: exit 1, a clear message, nothing written ----------------------

// A tetrahedron with outward (counter-clockwise) faces, then variants of it.
constexpr const char* kTetraVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
constexpr const char* kTetraFaces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

struct BadInput {
    const char* what;
    const char* file;      // file name written into the scratch folder (nullptr: none)
    std::string contents;
    const char* expected;  // in the error message
};

std::vector<BadInput> badInputs() {
    return {
        {"NaN vertex", "nan.obj", std::string("v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\n") + kTetraFaces, "not finite"},
        {"out-of-range index", "index.obj", std::string(kTetraVertices) + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 9\n",
         "index out of range"},
        {"empty file", "empty.obj", "", "empty.obj: cannot read the mesh"},
        {"non-manifold edge", "fin.obj", std::string(kTetraVertices) + "v 1 1 1\n" + kTetraFaces + "f 2 3 5\n",
         "non-manifold edge"},
        {"inconsistent winding", "winding.obj", std::string(kTetraVertices) + "f 1 3 2\nf 1 4 2\nf 1 4 3\nf 2 3 4\n",
         "inconsistent winding"},
        {"missing file", nullptr, "", "no such file"},
        {"unsupported extension", "tetra.xyz", std::string(kTetraVertices) + kTetraFaces, "unsupported mesh format"},
    };
}

TEST(OpalBakeCli, MalformedInputsFailWithAClearMessageAndWriteNothing) {
    for (const BadInput& bad : badInputs()) {
        SCOPED_TRACE(bad.what);
        const ScratchDir dir;
        const std::filesystem::path input = dir / (bad.file ? bad.file : "absent.obj");
        if (bad.file) test::writeText(input, bad.contents);
        const std::vector<std::string> before = dir.list();
        const test::RunResult r = bake(with({input.string(), "-o", (dir / "out").string(), "--json",
                                             (dir / "report.json").string()},
                                            kSmall));
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find("opal-bake: error: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(bad.expected), std::string::npos) << "expected '" << bad.expected << "' in:\n" << r.err;
        EXPECT_EQ(dir.list(), before) << "a failed bake must write nothing";
    }
}

TEST(OpalBakeCli, AValidTetrahedronBakes) {
    // The control for the refusals above: the same file without the defect bakes.
    const ScratchDir dir;
    test::writeText(dir / "tetra.obj", std::string(kTetraVertices) + kTetraFaces);
    const test::RunResult r = bake(with({(dir / "tetra.obj").string(), "-o", (dir / "tetra").string(), "-q"}, kSmall));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> expected = {"tetra.obj", test::sidecarNamedBy(dir / "tetra.usda"), "tetra.usda"};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(dir.list(), expected);
}

TEST(OpalBakeCli, AFileNameThatIsNoPrimNameGivesAReadableAsset) {
    // The bunny's file is stanford-bunny_...: the asset is named for its prim, in both halves.
    const ScratchDir dir;
    test::writeText(dir / "3d-tetra.obj", std::string(kTetraVertices) + kTetraFaces);
    const test::RunResult r =
        bake(with({(dir / "3d-tetra.obj").string(), "-o", (dir / "3d-tetra").string(), "-q"}, kSmall));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readAsset(dir / "3d-tetra.usda").name, "_3d_tetra");
}

// ---- bad arguments ------------------------------------------------------------------

TEST(OpalBakeCli, BadArgumentsNameTheProblem) {
    struct BadArgs {
        std::vector<std::string> args;
        std::vector<int> codes;  // acceptable exit codes
        std::vector<std::string> expected;
    };
    const std::vector<BadArgs> cases = {
        // Not M x 4^n: the message offers the nearest valid counts (768 = 3 x 16 x 16, 1024).
        {{"--samples", "1000"}, {1, 2}, {"1000", "768", "1024"}},
        {{"--keep", "0"}, {2}, {"--keep"}},
        {{"--energy", "1.5"}, {2}, {"--energy"}},
        {{"--material", "unobtainium"}, {1, 2}, {"--material", "unobtainium", "marble"}},
        {{"--env-res", "24"}, {1, 2}, {"--env-res", "power of two"}},
        {{"--range", "sigmaS=2:1"}, {2}, {"--range", "sigmaSPrime [2, 1]"}},
        // eta outside the dipole's range [1, 3] (schema/scatter/dipole.h), either bound.
        {{"--range", "eta=1.2:3.9"}, {2}, {"--range", "eta = 3.9", "[1, 3]"}},
        {{"--range", "eta=1.2:10"}, {2}, {"--range", "eta = 10", "[1, 3]"}},
        {{"--range", "eta=1.2:nan"}, {2}, {"--range", "eta = nan", "[1, 3]"}},
        {{"--range", "eta=0.5:1.6"}, {2}, {"--range", "eta = 0.5", "[1, 3]"}},
        {{"--no-such-option"}, {2}, {"--no-such-option"}},
    };
    for (const BadArgs& c : cases) {
        SCOPED_TRACE(test::joined(c.args));
        const ScratchDir dir;
        std::vector<std::string> args = {"builtin:candle", "-o", (dir / "out").string(), "--level", "0"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const test::RunResult r = bake(args);
        EXPECT_TRUE(std::find(c.codes.begin(), c.codes.end(), r.exitCode) != c.codes.end())
            << "exit code " << r.exitCode << "\n" << r.err;
        for (const std::string& e : c.expected)
            EXPECT_NE(r.err.find(e), std::string::npos) << "expected '" << e << "' in:\n" << r.err;
        EXPECT_TRUE(dir.list().empty());
    }
    // No output stem at all.
    const test::RunResult r = bake({"builtin:candle"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
    // --help is not an error.
    const test::RunResult help = bake({"--help"});
    EXPECT_EQ(help.exitCode, 0) << help.err;
    EXPECT_NE(help.out.find("--samples"), std::string::npos);
}

// ---- the JSON report ----------------------------------------------------------------

TEST(OpalBakeCli, JsonReportHasEveryKeyWithConsistentValues) {
    const ScratchDir dir;
    const test::RunResult r = bake(with({"builtin:candle", "-o", (dir / "candle").string(), "--json",
                                         (dir / "report.json").string(), "--quiet"},
                                        kSmall));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string sidecarName = test::sidecarNamedBy(dir / "candle.usda");
    EXPECT_EQ(dir.list(), (std::vector<std::string>{sidecarName, "candle.usda", "report.json"}));
    const nlohmann::json j = nlohmann::json::parse(test::readBytes(dir / "report.json"));
    for (const char* key : {"samples", "charts", "grid", "subdivision_level", "render_vertices", "raw_bytes", "step1_bytes", "step1_per_row", "step1_budget",
                            "step2_bytes", "sidecar_bytes", "compression_ratio", "energy_kept",
                            "transfer_rel_rmse", "seconds", "peak_rss_bytes", "warnings", "options"})
        EXPECT_TRUE(j.contains(key)) << key;

    const TranslucentAsset asset = readAsset(dir / "candle.usda");
    const std::uint64_t N = 256, K = std::uint64_t(BakeOptions{}.basisCount);
    EXPECT_EQ(j["samples"].get<std::uint64_t>(), N);
    EXPECT_EQ(j["charts"].get<std::uint64_t>(), 1u);
    EXPECT_EQ(j["grid"].get<std::uint64_t>(), 16u);
    EXPECT_EQ(j["render_vertices"].get<std::uint64_t>(), asset.mesh.points.size());
    EXPECT_EQ(j["raw_bytes"].get<std::uint64_t>(), N * N * K * 4);
    // Step 1 keeps max(1% of N, 256) coefficients per row of each T_k on average over k: at
    // 256 samples the floor, every coefficient (index + value per entry).
    EXPECT_EQ(j["step1_bytes"].get<std::uint64_t>(), N * N * K * 8);
    EXPECT_EQ(j["step1_per_row"].get<double>(), double(N));
    EXPECT_EQ(j["step1_budget"].get<std::string>(), "keep_min: keep x samples is fewer");
    std::uint64_t nonZeros = 0;
    for (const SparseMatrix& m : asset.transfer.perBasis) nonZeros += m.nonZeros();
    EXPECT_EQ(j["step2_bytes"].get<std::uint64_t>(), nonZeros * 8);
    const std::uint64_t sidecar = std::filesystem::file_size(dir / sidecarName);
    EXPECT_EQ(j["sidecar_file"].get<std::string>(), (dir / sidecarName).string());
    EXPECT_EQ(j["sidecar_bytes"].get<std::uint64_t>(), sidecar);
    EXPECT_DOUBLE_EQ(j["compression_ratio"].get<double>(), double(N * N * K * 4) / double(sidecar));
    const double energy = j["energy_kept"].get<double>();
    EXPECT_GE(energy, TransferSettings{}.energyFraction);  // the default
    EXPECT_LE(energy, 1.0);
    // The asset read back holds the material as float: the same error up to that rounding
    // (1.4e-6 relative in the material, through the nonnegative profile projection; it
    // moved the error by 3e-9 of its 2e-4, measured with the 36-function harmonic transfer).
    const double rmse = j["transfer_rel_rmse"].get<double>();
    EXPECT_NEAR(rmse, measureTransferError(asset, 1), std::max(1e-5 * rmse, 1e-8));
    EXPECT_GT(rmse, 0.0);
    double stages = 0.0;
    for (const auto& [stage, s] : j["seconds"].items())
        if (stage != "total") {
            EXPECT_GE(s.get<double>(), 0.0) << stage;
            stages += s.get<double>();
        }
    EXPECT_TRUE(j["seconds"].contains("transfer"));
    EXPECT_NEAR(j["seconds"]["total"].get<double>(), stages, 1e-9);
    EXPECT_GT(j["seconds"]["total"].get<double>(), 0.0);
    const auto rss = j["peak_rss_bytes"].get<std::uint64_t>();
    EXPECT_GT(rss, 4u << 20);   // a process that baked anything holds megabytes
    EXPECT_LT(rss, 4ull << 30);  // and a 256-sample bake nowhere near gigabytes
    EXPECT_EQ(j["options"]["samples"].get<std::uint64_t>(), N);
    EXPECT_EQ(j["options"]["input"].get<std::string>(), "builtin:candle");
}

// ---- progress output ----------------------------------------------------------------

TEST(OpalBakeCli, QuietBakePrintsNothing) {
    const ScratchDir dir;
    const test::RunResult r = bake(with({"builtin:candle", "-o", (dir / "candle").string(), "--quiet"}, kSmall));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, "");
}

TEST(OpalBakeCli, ProgressIsPlainLinesWhenStderrIsNotATerminal) {
    const ScratchDir dir;
    const test::RunResult r = bake(with({"builtin:candle", "-o", (dir / "candle").string()}, kSmall));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << "no bar redraws on a pipe";
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "no terminal escapes on a pipe";
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.back(), '\n');
    for (const char* stage : {"subdivide", "sample + parameterize", "fit profile basis", "transfer step 1 (Haar)",
                              "transfer step 2 (CDF 9/7)", "environment visibility", "measure transfer error"}) {
        EXPECT_NE(r.err.find(std::string("opal-bake: ") + stage + "...\n"), std::string::npos) << stage;
        EXPECT_NE(r.err.find(std::string("opal-bake: ") + stage + " done in "), std::string::npos) << stage;
    }
    EXPECT_NE(r.err.find("opal-bake: wrote " + (dir / "candle").string() + ".usda"), std::string::npos) << r.err;
    std::istringstream lines(r.err);
    for (std::string line; std::getline(lines, line);)
        EXPECT_TRUE(line.rfind("opal-bake: ", 0) == 0 || line.rfind("  ", 0) == 0) << "unexpected line: " << line;
}

// ---- interruption -------------------------------------------------------------------

// A bake that spends seconds in the transfer (8192 samples, 2 charts of 64 x 64) is
// signalled as soon as its stderr says the transfer has started.
struct Interrupted {
    int exitCode = -1;
    int termSignal = 0;
    std::string err;
};

Interrupted interruptDuringTransfer(const std::filesystem::path& stem, int sig) {
    test::ChildProcess child({OPAL_BAKE_EXE, "builtin:candle", "-o", stem.string(), "--samples", "8192", "--level",
                              "1", "--json", (stem.parent_path() / "report.json").string()});
    Interrupted out;
    const bool started = child.waitForStderr("opal-bake: transfer step 1", 120s);
    EXPECT_TRUE(started) << "the bake never reached the transfer:\n" << child.err();
    if (!started) return out;  // ~ChildProcess kills it
    EXPECT_TRUE(child.running());
    child.signal(sig);
    EXPECT_TRUE(child.wait(60s)) << "no exit within 60 s of the signal";
    out.exitCode = child.exitCode();
    out.termSignal = child.termSignal();
    out.err = child.err();
    return out;
}

TEST(OpalBakeCli, SigtermDuringTheTransferExits143AndWritesNothing) {
    const ScratchDir dir;
    const Interrupted r = interruptDuringTransfer(dir / "candle", SIGTERM);
    EXPECT_EQ(r.termSignal, 0) << "the handler must turn the signal into an orderly exit";
    EXPECT_EQ(r.exitCode, 143) << r.err;
    EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
    EXPECT_TRUE(dir.list().empty()) << "left behind: " << test::joined(dir.list());
}

TEST(OpalBakeCli, SigintDuringTheTransferExits130AndKeepsThePreviousAsset) {
    const ScratchDir dir;
    const test::RunResult first = bake(with({"builtin:candle", "-o", (dir / "candle").string(), "-q"}, kSmall));
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const std::string sidecar = test::sidecarNamedBy(dir / "candle.usda");
    const std::string usda = test::readBytes(dir / "candle.usda"), opal = test::readBytes(dir / sidecar);

    const Interrupted r = interruptDuringTransfer(dir / "candle", SIGINT);
    EXPECT_EQ(r.termSignal, 0);
    EXPECT_EQ(r.exitCode, 130) << r.err;
    EXPECT_EQ(dir.list(), (std::vector<std::string>{sidecar, "candle.usda"}));
    EXPECT_TRUE(test::readBytes(dir / "candle.usda") == usda);
    EXPECT_TRUE(test::readBytes(dir / sidecar) == opal);
    EXPECT_EQ(readAsset(dir / "candle.usda").samples.size(), 256u);
}

}  // namespace
}  // namespace opal
