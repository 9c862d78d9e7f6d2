// `opal-bench bake`: the bake pipeline's cost and compression, in the form of the paper's
// Table 1 (raw transfer, after step 1, after step 2), with the opal-bake issue's targets
// next to the numbers. Each row is one run of the opal-bake executable, so that every row
// has its own peak memory (peak RSS is per process) and the numbers are what a user gets.
//
// Default table (meshes from the shared test assets, ../shared/assets beside the source
// tree, or --assets / $OPAL_SHARED_ASSETS):
//   - the Stanford bunny (watertight, 69,664 triangles, millimetres) at 16,384 and 65,536
//     samples with opal-bake's defaults: --level auto picks level 0 at 16,384 (the scan's
//     34,834 vertices outnumber the samples) and level 1 at 65,536.
//   - Spot's Catmull-Clark cage (180 polygons) at level 3 (about 11,500 quads), 16,384
//     samples, 0.0171 units per mm: Spot's limit surface is 1.71 units long (nose to tail,
//     z), so Spot is a 100 mm cow figurine (marble's few-mm mean free path then reads as
//     translucent).
// The lvl column is the level the bake used. Other meshes: --mesh PATH (repeatable) with
// --samples (repeatable), --level and
// --units-per-mm.
#include "bench/output_folder.h"
#include "bench/subcommand.h"
#include "schema/usd/atomic_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace opal::bench {

// Declared here until bench/subcommand.h lists it (main.cpp's table must add it too).
Subcommand bakeSubcommand();

namespace {

namespace fs = std::filesystem;

// The targets.
constexpr double kSeconds16k = 30.0;        // 16,384 samples
constexpr double kSeconds64k = 300.0;       // 65,536 samples
constexpr double kPeakBytes64k = 8.0 * (1ull << 30);
constexpr double kSidecarBytes64k = 150.0 * (1 << 20);  // "150 MB", read as MiB like opal-bake's summary
constexpr double kRatio64k = 1000.0;
constexpr double kRelRmse = 0.01;

struct Row {
    std::string name;  // label in the table
    fs::path mesh;
    std::uint64_t samples = 16384;
    std::string level = "auto";  // as opal-bake's --level
    double unitsPerMm = 1.0;
};

struct Options {
    std::vector<std::string> meshes;
    std::vector<std::uint64_t> samples;
    std::string level = "auto";
    double unitsPerMm = 1.0;
    std::uint64_t maxSamples = 0;  // 0: no limit
    fs::path outputDir = "out/bake";
    fs::path jsonFile;
    fs::path assets;
    fs::path bakeExe;
    bool quiet = false;
};

struct Result {
    Row row;
    double wallSeconds = 0.0;
    std::uint64_t childMaxRssBytes = 0;  // from wait4, a cross-check of the report's value
    double loadBefore = -1.0, loadAfter = -1.0;  // 1-minute load average: times depend on it
    nlohmann::ordered_json report;  // opal-bake's, stages in order
};

// ../shared/assets beside the source tree, as the tests' OPAL_SHARED_ASSETS.
fs::path sharedAssets(const Options& o) {
    if (!o.assets.empty()) return o.assets;
    if (const char* env = std::getenv("OPAL_SHARED_ASSETS"); env && *env) return env;
    return fs::path(__FILE__).parent_path().parent_path().parent_path() / "shared" / "assets";
}

// opal-bake beside opal-bench (an install), or in the build tree's bake/ folder.
fs::path findBakeExe(const Options& o) {
    if (!o.bakeExe.empty()) return o.bakeExe;
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        for (const fs::path& candidate :
             {self.parent_path() / "opal-bake", self.parent_path().parent_path() / "bake" / "opal-bake"})
            if (fs::is_regular_file(candidate, ec)) return candidate;
    }
    throw std::runtime_error("cannot find the opal-bake executable next to opal-bench or in the build tree's bake/ "
                             "(build the opal-bake target, or pass --bake-exe)");
}

std::vector<Row> defaultRows(const Options& o) {
    const fs::path meshes = sharedAssets(o) / "meshes";
    const fs::path bunny = meshes / "stanford-bunny_watertight_quartet.obj";
    const fs::path spot = meshes / "spot_control_mesh.obj";
    return {{"bunny", bunny, 16384, "auto", 1.0}, {"bunny", bunny, 65536, "auto", 1.0}, {"spot", spot, 16384, "3", 0.0171}};
}

std::vector<Row> requestedRows(const Options& o) {
    std::vector<Row> rows;
    const std::vector<std::uint64_t> counts = o.samples.empty() ? std::vector<std::uint64_t>{16384} : o.samples;
    for (const std::string& mesh : o.meshes)
        for (std::uint64_t n : counts) rows.push_back({fs::path(mesh).stem().string(), mesh, n, o.level, o.unitsPerMm});
    return rows;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string numberText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// Runs opal-bake for one row; returns its exit code (128 + signal when a signal ended it).
int runBake(const fs::path& exe, const Row& row, const fs::path& stem, const fs::path& json, bool quiet,
            Result& result) {
    std::vector<std::string> args = {exe.string(),       row.mesh.string(),
                                     "-o",               stem.string(),
                                     "--samples",        std::to_string(row.samples),
                                     "--level",          row.level,
                                     "--units-per-mm",   numberText(row.unitsPerMm),
                                     "--json",           json.string()};
    if (quiet) args.push_back("--quiet");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    if (const int rc = posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ); rc != 0)
        throw std::runtime_error("cannot start " + exe.string() + ": " + std::strerror(rc));
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0)
        if (errno != EINTR) throw std::runtime_error(std::string("wait4: ") + std::strerror(errno));
    result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.childMaxRssBytes = std::uint64_t(usage.ru_maxrss) * 1024;  // Linux: kilobytes
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return WEXITSTATUS(status);
}

double loadAverage() {
    double load = -1.0;
    return getloadavg(&load, 1) == 1 ? load : -1.0;
}

const char* verdict(bool ok) { return ok ? "ok" : "MISSED"; }

double mib(double bytes) { return bytes / double(1 << 20); }

std::uint64_t u64(const nlohmann::ordered_json& j, const char* key) { return j.at(key).get<std::uint64_t>(); }
double f64(const nlohmann::ordered_json& j, const char* key) { return j.at(key).get<double>(); }

// The targets that apply to a row, as (label, met) pairs.
std::vector<std::pair<std::string, bool>> targets(const Result& r) {
    const nlohmann::ordered_json& j = r.report;
    std::vector<std::pair<std::string, bool>> t;
    const std::uint64_t n = u64(j, "samples");
    if (n == 16384) t.push_back({"time <= 30 s", r.wallSeconds <= kSeconds16k});
    if (n == 65536) {
        t.push_back({"time <= 5 min", r.wallSeconds <= kSeconds64k});
        t.push_back({"peak <= 8 GiB", double(u64(j, "peak_rss_bytes")) <= kPeakBytes64k});
        t.push_back({"sidecar <= 150 MiB", double(u64(j, "sidecar_bytes")) <= kSidecarBytes64k});
        t.push_back({"ratio >= 1000x", f64(j, "compression_ratio") >= kRatio64k});
    }
    t.push_back({"rel. RMSE <= 1%", f64(j, "transfer_rel_rmse") <= kRelRmse});
    return t;
}

void printTable(const std::vector<Result>& results) {
    int w = 5;  // the model column fits the longest name
    for (const Result& r : results) w = std::max(w, int(r.row.name.size()));
    std::printf("\nBake cost and transfer compression (cf. the paper's Table 1); one opal-bake process per row\n\n");
    std::printf("%-*s %7s %3s %8s %9s %10s %10s %10s %11s %7s %7s %8s %7s %8s\n", w, "model", "samples", "lvl",
                "charts", "vertices", "raw MiB", "step1 MiB", "step2 MiB", "sidecar MiB", "ratio", "energy",
                "rel.RMSE", "time s", "peak MiB");
    for (const Result& r : results) {
        const nlohmann::ordered_json& j = r.report;
        char charts[32];
        std::snprintf(charts, sizeof charts, "%llux%llu^2", (unsigned long long)u64(j, "charts"),
                      (unsigned long long)u64(j, "grid"));
        std::printf("%-*s %7llu %3u %8s %9llu %10.1f %10.1f %10.1f %11.2f %6.0fx %7.5f %7.3f%% %7.1f %8.0f\n", w,
                    r.row.name.c_str(), (unsigned long long)u64(j, "samples"), unsigned(u64(j, "subdivision_level")), charts,
                    (unsigned long long)u64(j, "render_vertices"), mib(double(u64(j, "raw_bytes"))),
                    mib(double(u64(j, "step1_bytes"))), mib(double(u64(j, "step2_bytes"))),
                    mib(double(u64(j, "sidecar_bytes"))), f64(j, "compression_ratio"), f64(j, "energy_kept"),
                    100.0 * f64(j, "transfer_rel_rmse"), r.wallSeconds, mib(double(u64(j, "peak_rss_bytes"))));
    }
    std::printf("\n(MiB = 2^20 bytes, as in opal-bake's summary; raw = N x N x K float32; step 1/2 = retained entries x 8 bytes (index + "
                "value);\n sidecar = the .opal file (zstd); time = the whole opal-bake process; peak = its peak "
                "resident memory)\n\ntargets:\n");
    for (const Result& r : results) {
        std::printf("  %-*s %6llu:", w, r.row.name.c_str(), (unsigned long long)u64(r.report, "samples"));
        for (const auto& [label, met] : targets(r)) std::printf("  %s %s;", label.c_str(), verdict(met));
        std::printf("\n");
    }
    std::printf("\nstage seconds (machine load average before / after):\n");
    for (const Result& r : results) {
        std::printf("  %-*s %6llu (load %.1f / %.1f):", w, r.row.name.c_str(),
                    (unsigned long long)u64(r.report, "samples"), r.loadBefore, r.loadAfter);
        for (const auto& [stage, s] : r.report.at("seconds").items())
            std::printf(" %s %.1f", stage.c_str(), s.get<double>());
        std::printf("\n");
    }
}

nlohmann::ordered_json resultsJson(const std::vector<Result>& results) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const Result& r : results) {
        nlohmann::ordered_json t = nlohmann::ordered_json::object();
        for (const auto& [label, met] : targets(r)) t[label] = met;
        rows.push_back({{"name", r.row.name},
                        {"mesh", r.row.mesh.string()},
                        {"samples", r.row.samples},
                        {"level", r.row.level},
                        {"units_per_mm", r.row.unitsPerMm},
                        {"wall_seconds", r.wallSeconds},
                        {"child_max_rss_bytes", r.childMaxRssBytes},
                        {"load_average_before", r.loadBefore},
                        {"load_average_after", r.loadAfter},
                        {"targets_met", t},
                        {"report", r.report}});
    }
    return {{"rows", rows}};
}

int runBakeBench(int argc, char** argv) {
    CLI::App app{"Bake time, peak memory and transfer compression per mesh (the paper's Table 1)", "opal-bench bake"};
    Options options;
    app.add_option("--mesh", options.meshes, "mesh to bake (repeatable); default: the bunny and Spot table");
    app.add_option("--samples", options.samples, "sample counts for --mesh (repeatable; default 16384)");
    app.add_option("--level", options.level, "subdivision level for --mesh (0-6 or auto)")
        ->check(CLI::IsMember({"auto", "0", "1", "2", "3", "4", "5", "6"}))
        ->capture_default_str();
    app.add_option("--units-per-mm", options.unitsPerMm, "scene units per mm for --mesh")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--max-samples", options.maxSamples,
                   "skip rows with more samples than this (e.g. 16384 to leave out the heavy 65,536 bunny)");
    app.add_option("-o,--output", options.outputDir, "folder for the baked assets and per-row reports")
        ->capture_default_str();
    app.add_option("--json", options.jsonFile, "also write the results as JSON to this file");
    app.add_option("--assets", options.assets, "the shared assets folder (default: $OPAL_SHARED_ASSETS, else "
                                               "../shared/assets beside the source tree)");
    app.add_option("--bake-exe", options.bakeExe, "the opal-bake executable (default: found beside opal-bench)");
    app.add_flag("-q,--quiet", options.quiet, "no progress output from opal-bake");
    CLI11_PARSE(app, argc, argv);
    try {
        const fs::path exe = findBakeExe(options);
        ensureDirectory(options.outputDir);
        if (!options.jsonFile.empty())
            ensureDirectory(options.jsonFile.parent_path().empty() ? "." : options.jsonFile.parent_path());
        const std::vector<Row> rows = options.meshes.empty() ? defaultRows(options) : requestedRows(options);
        std::vector<Result> results;
        for (const Row& row : rows) {
            if (options.maxSamples && row.samples > options.maxSamples) {
                std::printf("opal-bench bake: skipping %s at %llu samples (--max-samples %llu)\n", row.name.c_str(),
                            (unsigned long long)row.samples, (unsigned long long)options.maxSamples);
                continue;
            }
            if (std::error_code ec; !fs::is_regular_file(row.mesh, ec)) {
                std::printf("opal-bench bake: skipping %s: %s not found (pass --assets or set OPAL_SHARED_ASSETS)\n",
                            row.name.c_str(), row.mesh.c_str());
                continue;
            }
            const std::string id = row.name + "_" + std::to_string(row.samples) + "_L" + row.level;
            const fs::path stem = options.outputDir / id, json = options.outputDir / (id + ".json");
            std::printf("opal-bench bake: %s: %s, %llu samples, level %s, %s units/mm\n", id.c_str(),
                        row.mesh.c_str(), (unsigned long long)row.samples, row.level.c_str(),
                        numberText(row.unitsPerMm).c_str());
            std::fflush(stdout);
            fs::remove(json);
            Result result;
            result.row = row;
            result.loadBefore = loadAverage();
            const int code = runBake(exe, row, stem, json, options.quiet, result);
            result.loadAfter = loadAverage();
            if (code == 130 || code == 143) {
                std::fprintf(stderr, "opal-bench bake: interrupted\n");
                return code;
            }
            if (code != 0) {
                std::fprintf(stderr, "opal-bench bake: opal-bake failed on %s (exit %d); row skipped\n", id.c_str(),
                             code);
                continue;
            }
            result.report = nlohmann::ordered_json::parse(readFile(json));
            results.push_back(std::move(result));
        }
        if (results.empty()) {
            std::fprintf(stderr, "opal-bench bake: no row was baked\n");
            return 1;
        }
        printTable(results);
        if (!options.jsonFile.empty()) {
            writeFileAtomically(options.jsonFile, resultsJson(results).dump(2) + "\n");
            std::printf("\nwrote %s\n", options.jsonFile.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench bake: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace

Subcommand bakeSubcommand() {
    return {"bake", "bake time, peak memory and transfer compression (Table 1) via the opal-bake executable",
            runBakeBench};
}

}  // namespace opal::bench
