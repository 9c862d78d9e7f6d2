// `opal-bench transfer-row`: the cost of one row of the bake's transfer step 1
// (docs/ARCHITECTURE.md#compression) at N samples: evaluating T_k[o][i] = b_k(|x_o - x_i|) A_i for
// all K, the Haar transform of each of the K rows per chart, and keeping each row's largest 1%.
// Every stage is timed against the straightforward implementation it replaced (kept below as the
// reference), in the same run, on the same rows, and checked to give the same bits. From the
// per-row times: the projected step-1 time for N rows on this machine (rows x per-row / cores), and
// the same measured with all cores on a batch of rows.
//
// The scene is synthetic: N points on a sphere (Fibonacci lattice, radius 50 mm, so the
// default basis is fitted for the 173 mm box diagonal as opal-bake would), ordered into
// the bake's charts by parameterizeCharts. The new pipeline writes its K rows with the
// padded stride transferRowStride(N) (see transfer_row.h), the old one with stride N.
#include "bake/chart_parameterization.h"
#include "bake/sample_count.h"
#include "bake/transfer_row.h"
#include "bench/median.h"
#include "bench/output_folder.h"
#include "bench/subcommand.h"
#include "schema/scatter/profile_basis.h"
#include "schema/usd/atomic_file.h"
#include "schema/wavelet/haar.h"
#include "schema/wavelet/nonstandard.h"
#include "schema/wavelet/sparse.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <functional>
#include <numbers>
#include <thread>
#include <vector>

namespace opal::bench {

namespace {

struct Options {
    std::uint64_t samples = 65536;
    int rows = 24;            // rows timed one by one (single thread)
    int batchRows = 128;      // rows timed as a parallel batch (all cores)
    double keepFraction = 0.01;
    double radiusMm = 50.0;
    std::filesystem::path jsonFile;
};

struct Scene {
    ChartLayout layout;
    std::vector<SurfaceSample> samples;  // grid order, mm
    ProfileBasis basis;
};

// N points on a sphere by the Fibonacci lattice (equal areas), in the bake's chart order.
Scene makeScene(const Options& options) {
    Scene scene;
    scene.layout = chartLayoutForSampleCount(options.samples);
    const std::size_t n = options.samples;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    std::vector<Imath::V3f> points(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / double(n);
        const double ring = std::sqrt(1.0 - z * z);
        points[i] = Imath::V3f(float(options.radiusMm * ring * std::cos(golden * i)),
                               float(options.radiusMm * ring * std::sin(golden * i)), float(options.radiusMm * z));
    }
    const std::vector<std::uint32_t> order = parameterizeCharts(points, scene.layout);
    const float area = float(4.0 * std::numbers::pi * options.radiusMm * options.radiusMm / double(n));
    for (std::uint32_t i : order) scene.samples.push_back({points[i], points[i].normalized(), area});
    ProfileBasisSettings settings;
    settings.rMax = 2.0 * std::sqrt(3.0) * options.radiusMm;  // the bounding box diagonal, as opal-bake
    scene.basis = ProfileBasis::fit(settings);
    return scene;
}

// ---- References: the implementations step 1 used before, kept to time against. ----

// The per-pair loop: Imath positions, BasisLookup::evaluate per pair, K strided stores.
void referenceRow(std::size_t o, std::span<const Imath::V3f> position, std::span<const float> area,
                  const BasisLookup& lookup, float* rows) {
    const std::size_t n = position.size();
    const Imath::V3f xo = position[o];
    float b[64];
    for (std::size_t i = 0; i < n; ++i) {
        lookup.evaluate((position[i] - xo).length(), b);
        for (int k = 0; k < lookup.K(); ++k) rows[k * n + i] = b[k] * area[i];
    }
}

// The Haar step as the generic nonstandard decomposition (nonstandard.h) ran it:
// deinterleave, butterfly, copy back, for rows then columns, per level.
struct ReferenceHaarStep {
    static void analyze(float* lo, float* hi, std::size_t half, std::size_t width) {
        const float invSqrt2 = 1.0f / std::numbers::sqrt2_v<float>;
        for (std::size_t j = 0; j < half * width; ++j) {
            const float a = lo[j], b = hi[j];
            lo[j] = (a + b) * invSqrt2;
            hi[j] = (a - b) * invSqrt2;
        }
    }
};

void referenceHaar(std::span<float> row, const ChartLayout& layout) {
    wavelet_detail::analyzeCharts<ReferenceHaarStep>(row, layout, 1, 1);
}

// keepLargest by std::nth_element over a copy of the magnitudes, then one collecting pass.
SparseVector referenceKeepLargest(std::span<const float> dense, std::size_t n, std::vector<float>& magnitudes) {
    magnitudes.resize(dense.size());
    std::size_t nonZeros = 0;
    for (std::size_t i = 0; i < dense.size(); ++i) {
        magnitudes[i] = std::abs(dense[i]);
        nonZeros += magnitudes[i] != 0.0f;
    }
    float threshold = 0.0f;
    std::size_t ties = nonZeros;
    if (n < nonZeros) {
        std::nth_element(magnitudes.begin(), magnitudes.begin() + (n - 1), magnitudes.end(), std::greater<float>());
        threshold = *std::min_element(magnitudes.begin(), magnitudes.begin() + n);
        ties = n - std::size_t(std::count_if(magnitudes.begin(), magnitudes.begin() + n,
                                             [&](float m) { return m > threshold; }));
    }
    SparseVector kept;
    for (std::uint32_t i = 0; i < dense.size(); ++i) {
        const float m = std::abs(dense[i]);
        bool take = m > threshold;
        if (!take && m == threshold && m > 0.0f && ties > 0) {
            take = true;
            --ties;
        }
        if (take) {
            kept.indices.push_back(i);
            kept.values.push_back(dense[i]);
        }
    }
    return kept;
}

// ---- Measurement. ----

template <typename F>
double secondsOf(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of the calling thread: on a machine shared with other jobs, the time this
// thread actually ran (wall time would include time slices given to others).
double threadSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <typename F>
double cpuSecondsOf(F&& f) {
    const double start = threadSeconds();
    f();
    return threadSeconds() - start;
}

// Per-row seconds of one stage (all K), reference and new, on the same rows.
struct StageTimes {
    std::vector<double> reference, fast;
    std::size_t mismatches = 0;  // values (or kept sets) that differ from the reference
};

// Per row of a whole step-1 row over a batch of rows with all cores: wall seconds, and
// CPU seconds of all threads (not inflated by other jobs' time slices).
struct BatchTimes {
    double wall = 0.0, cpu = 0.0;
};

struct Report {
    std::size_t n = 0;
    int K = 0;
    ChartLayout layout;
    std::size_t perRow = 0;
    unsigned cores = 1;
    StageTimes row, haar, keep;
    BatchTimes batchReference, batchFast;  // per row, all cores
    int batchRows = 0;
};

// K rows of N values, `stride` apart: the old pipeline's layout (stride N) or the new one's
// (transferRowStride(N)).
struct RowBuffer {
    std::size_t n = 0, stride = 0;
    std::vector<float> values;

    RowBuffer(int K, std::size_t n, std::size_t stride) : n(n), stride(stride), values((K - 1) * stride + n) {}
    std::span<float> row(int k) { return {values.data() + std::size_t(k) * stride, n}; }
};

// How many values of the K rows of a and b differ in their bits.
std::size_t bitDifferences(RowBuffer& a, RowBuffer& b, int K) {
    std::size_t count = 0;
    for (int k = 0; k < K; ++k)
        for (std::size_t i = 0; i < a.n; ++i) count += std::memcmp(&a.row(k)[i], &b.row(k)[i], sizeof(float)) != 0;
    return count;
}

struct Buffers {
    RowBuffer reference, fast;
    std::vector<float> magnitudes;

    Buffers(int K, std::size_t n) : reference(K, n, n), fast(K, n, transferRowStride(n)) {}
};

// One row through both pipelines in the bake's order (evaluate all K; then per k, Haar and
// keepLargest while the row is in cache), each stage's time summed over the K rows.
void measureRow(std::size_t o, const Scene& scene, const TransferSamples& mm, std::span<const Imath::V3f> position,
                const BasisLookup& lookup, std::size_t perRow, Buffers& b, Report& report) {
    const int K = lookup.K();
    report.row.reference.push_back(
        cpuSecondsOf([&] { referenceRow(o, position, mm.area, lookup, b.reference.values.data()); }));
    report.row.fast.push_back(cpuSecondsOf([&] { transferRow(o, mm, lookup, b.fast.values, b.fast.stride); }));
    report.row.mismatches += bitDifferences(b.reference, b.fast, K);
    double haarReference = 0.0, haarFast = 0.0, keepReference = 0.0, keepFast = 0.0;
    for (int k = 0; k < K; ++k) {
        SparseVector reference, fast;
        haarReference += cpuSecondsOf([&] { referenceHaar(b.reference.row(k), scene.layout); });
        keepReference += cpuSecondsOf([&] { reference = referenceKeepLargest(b.reference.row(k), perRow, b.magnitudes); });
        haarFast += cpuSecondsOf([&] { haarForwardCharts(b.fast.row(k), scene.layout); });
        keepFast += cpuSecondsOf([&] { fast = keepLargest(b.fast.row(k), perRow); });
        report.keep.mismatches += reference.indices != fast.indices || reference.values != fast.values;
    }
    report.haar.mismatches += bitDifferences(b.reference, b.fast, K);
    report.haar.reference.push_back(haarReference);
    report.haar.fast.push_back(haarFast);
    report.keep.reference.push_back(keepReference);
    report.keep.fast.push_back(keepFast);
}

double processSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The whole step-1 row (evaluate, then Haar and keepLargest per k) on `rows` rows spread
// over N, with all cores, as the bake's parallel loop runs it.
template <typename RowFn>
BatchTimes batchSecondsPerRow(std::size_t n, int K, int rows, RowFn&& rowFn) {
    tbb::enumerable_thread_specific<Buffers> scratch([&] { return Buffers(K, n); });
    scratch.local();  // allocate outside the timed region (other threads' on first use)
    const double cpuStart = processSeconds();
    const double wall = secondsOf([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, rows, 1), [&](const tbb::blocked_range<int>& range) {
            Buffers& b = scratch.local();
            for (int j = range.begin(); j != range.end(); ++j) rowFn(std::size_t(j) * n / rows, b);
        });
    });
    return {wall / rows, (processSeconds() - cpuStart) / rows};
}

Report measure(const Options& options, const Scene& scene) {
    Report report;
    report.n = scene.samples.size();
    report.layout = scene.layout;
    const BasisLookup lookup(scene.basis);
    report.K = lookup.K();
    report.perRow = std::size_t(std::clamp(std::ceil(options.keepFraction * double(report.n)), 1.0, double(report.n)));
    report.cores = std::max(1u, std::thread::hardware_concurrency());
    const TransferSamples mm = toTransferSamples(scene.samples, 1.0);
    std::vector<Imath::V3f> position;
    for (const SurfaceSample& s : scene.samples) position.push_back(s.position);
    const std::size_t n = report.n;
    const int K = report.K;
    {
        // One row at a time on one core (haarForwardCharts would otherwise split the charts
        // of one row over the cores).
        tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
        Buffers b(K, n);
        for (int j = 0; j < options.rows; ++j)
            measureRow(std::size_t(j) * n / options.rows, scene, mm, position, lookup, report.perRow, b, report);
    }
    report.batchRows = std::min<int>(options.batchRows, int(n));
    report.batchReference = batchSecondsPerRow(n, K, report.batchRows, [&](std::size_t o, Buffers& b) {
        referenceRow(o, position, mm.area, lookup, b.reference.values.data());
        for (int k = 0; k < K; ++k) {
            referenceHaar(b.reference.row(k), scene.layout);
            referenceKeepLargest(b.reference.row(k), report.perRow, b.magnitudes);
        }
    });
    report.batchFast = batchSecondsPerRow(n, K, report.batchRows, [&](std::size_t o, Buffers& b) {
        transferRow(o, mm, lookup, b.fast.values, b.fast.stride);
        for (int k = 0; k < K; ++k) {
            haarForwardCharts(b.fast.row(k), scene.layout);
            keepLargest(b.fast.row(k), report.perRow);
        }
    });
    return report;
}

double totalReference(const Report& r) {
    return median(r.row.reference) + median(r.haar.reference) + median(r.keep.reference);
}
double totalFast(const Report& r) { return median(r.row.fast) + median(r.haar.fast) + median(r.keep.fast); }

void printStage(const char* name, const StageTimes& s, const char* what) {
    const double ref = median(s.reference), fast = median(s.fast);
    std::printf("  %-28s %10.1f   %10.1f   %6.2fx   %zu %s\n", name, ref * 1e6, fast * 1e6, ref / fast, s.mismatches,
                what);
}

void printReport(const Report& r, const Options& options) {
    const double charts = double(r.layout.charts) * r.K;
    std::printf("transfer step 1, one row: N = %zu (%u charts of %u x %u), K = %d, keep %zu per row\n", r.n,
                r.layout.charts, r.layout.size(), r.layout.size(), r.K, r.perRow);
    std::printf("medians over %d rows, one thread, thread CPU time; reference = the implementation replaced\n\n",
                options.rows);
    std::printf("  stage (all K per row)         reference us     new us    ratio   differences\n");
    printStage("evaluate b_k(r) A_i", r.row, "values");
    printStage("Haar per chart (x K)", r.haar, "values");
    printStage("keepLargest (x K)", r.keep, "kept sets");
    std::printf("  %-28s %10.1f   %10.1f   %6.2fx\n", "whole row", totalReference(r) * 1e6, totalFast(r) * 1e6,
                totalReference(r) / totalFast(r));
    std::printf("  Haar per chart: %.2f us reference, %.2f us new\n\n", median(r.haar.reference) / charts * 1e6,
                median(r.haar.fast) / charts * 1e6);
    std::printf("projected step 1 for %zu rows on %u cores (rows x per-row / cores): reference %.1f s, new %.1f s\n",
                r.n, r.cores, double(r.n) * totalReference(r) / r.cores, double(r.n) * totalFast(r) / r.cores);
    std::printf("measured with all cores on %d rows, scaled to %zu rows: wall: reference %.1f s, new %.1f s\n",
                r.batchRows, r.n, double(r.n) * r.batchReference.wall, double(r.n) * r.batchFast.wall);
    std::printf("  (CPU time of all threads / cores:                  reference %.1f s, new %.1f s)\n",
                double(r.n) * r.batchReference.cpu / r.cores, double(r.n) * r.batchFast.cpu / r.cores);
}

nlohmann::json stageJson(const StageTimes& s) {
    return {{"reference_us", median(s.reference) * 1e6},
            {"new_us", median(s.fast) * 1e6},
            {"ratio", median(s.reference) / median(s.fast)},
            {"differences", s.mismatches}};
}

std::string reportJson(const Report& r, const Options& options) {
    nlohmann::json json;
    json["samples"] = r.n;
    json["charts"] = r.layout.charts;
    json["chart_size"] = r.layout.size();
    json["K"] = r.K;
    json["kept_per_row"] = r.perRow;
    json["rows_timed"] = options.rows;
    json["cores"] = r.cores;
    json["evaluate"] = stageJson(r.row);
    json["haar"] = stageJson(r.haar);
    json["haar"]["per_chart_reference_us"] = median(r.haar.reference) / (r.layout.charts * r.K) * 1e6;
    json["haar"]["per_chart_new_us"] = median(r.haar.fast) / (r.layout.charts * r.K) * 1e6;
    json["keep_largest"] = stageJson(r.keep);
    json["row_reference_us"] = totalReference(r) * 1e6;
    json["row_new_us"] = totalFast(r) * 1e6;
    json["projected_step1_reference_s"] = double(r.n) * totalReference(r) / r.cores;
    json["projected_step1_new_s"] = double(r.n) * totalFast(r) / r.cores;
    json["batch_rows"] = r.batchRows;
    json["batch_step1_reference_wall_s"] = double(r.n) * r.batchReference.wall;
    json["batch_step1_new_wall_s"] = double(r.n) * r.batchFast.wall;
    json["batch_step1_reference_cpu_per_core_s"] = double(r.n) * r.batchReference.cpu / r.cores;
    json["batch_step1_new_cpu_per_core_s"] = double(r.n) * r.batchFast.cpu / r.cores;
    return json.dump(2) + "\n";
}

int runTransferRow(int argc, char** argv) {
    CLI::App app{"Per-row cost of the bake's transfer step 1 (evaluate, Haar, keep largest) vs the old code",
                 "opal-bench transfer-row"};
    Options options;
    app.add_option("--samples", options.samples, "N, a valid bake sample count (M x 4^n)")->capture_default_str();
    app.add_option("--rows", options.rows, "rows timed one at a time")->check(CLI::Range(1, 100000))->capture_default_str();
    app.add_option("--batch-rows", options.batchRows, "rows timed as one parallel batch")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    app.add_option("--json", options.jsonFile, "also write the results as JSON to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!options.jsonFile.empty())
            ensureDirectory(options.jsonFile.parent_path().empty() ? "." : options.jsonFile.parent_path());
        const Scene scene = makeScene(options);
        const Report report = measure(options, scene);
        printReport(report, options);
        if (!options.jsonFile.empty()) writeFileAtomically(options.jsonFile, reportJson(report, options));
        return report.row.mismatches + report.haar.mismatches + report.keep.mismatches == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench transfer-row: %s\n", e.what());
        return 1;
    }
}

}  // namespace

Subcommand transferRowSubcommand() {
    return {"transfer-row", "per-row cost of the bake's transfer step 1 vs the code it replaced", runTransferRow};
}

}  // namespace opal::bench
