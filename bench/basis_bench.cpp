// `opal-bench basis`: accuracy of the PCA profile basis (docs/ARCHITECTURE.md#pca) against the
// exact dipole, over held-out random materials and the ten Jensen presets, for K = 4..20,
// plus the paper's Figure 2 (first four basis functions, eigenvalue spectrum).
#include "bench/output_folder.h"
#include "bench/plot.h"
#include "bench/subcommand.h"
#include "schema/scatter/material_sampler.h"
#include "schema/scatter/profile_basis.h"
#include "schema/usd/atomic_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numeric>
#include <sstream>

namespace opal::bench {

namespace {

constexpr std::array kBasisSizes = {4, 8, 12, 16, 20};
constexpr int kHeldOutMaterials = 1000;
constexpr std::uint64_t kHeldOutSeed = 20240607;  // the training set uses ProfileBasisSettings::seed

struct Options {
    std::filesystem::path outputDir = "out/basis";
    std::filesystem::path jsonFile;
    double rMax = 0.0;
};

struct ErrorRow {
    int K = 0;
    double mean = 0.0, max = 0.0;              // held-out random materials
    double presetMean = 0.0, presetMax = 0.0;  // 10 presets x 3 channels
};

struct Report {
    ProfileBasis basis;
    double fitSeconds = 0.0;
    std::vector<ErrorRow> rows;
};

std::vector<DipoleCoefficients> presetChannels() {
    std::vector<DipoleCoefficients> channels;
    for (const NamedMaterial& preset : jensenPresets())
        for (int c = 0; c < 3; ++c) channels.push_back(preset.material.channel(c));
    return channels;
}

// errors[i][j]: relative error of material j with kBasisSizes[i] terms.
std::vector<std::vector<double>> relativeErrors(const ProfileBasis& basis, const std::vector<DipoleCoefficients>& m) {
    std::vector<std::vector<double>> errors(kBasisSizes.size(), std::vector<double>(m.size()));
    tbb::parallel_for(std::size_t{0}, m.size(), [&](std::size_t j) {
        for (std::size_t i = 0; i < kBasisSizes.size(); ++i) errors[i][j] = basis.relativeError(m[j], kBasisSizes[i]);
    });
    return errors;
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }
double maximum(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

Report measure(const Options& options) {
    ProfileBasisSettings settings;
    settings.K = kBasisSizes.back();
    settings.rMax = options.rMax;
    const auto start = std::chrono::steady_clock::now();
    Report report{ProfileBasis::fit(settings), 0.0, {}};
    report.fitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const auto heldOut = relativeErrors(report.basis, sampleChannels(settings.range, kHeldOutMaterials, kHeldOutSeed));
    const auto presets = relativeErrors(report.basis, presetChannels());
    for (std::size_t i = 0; i < kBasisSizes.size(); ++i)
        report.rows.push_back(
            {kBasisSizes[i], mean(heldOut[i]), maximum(heldOut[i]), mean(presets[i]), maximum(presets[i])});
    return report;
}

void printTable(const Report& report) {
    const ProfileBasis& b = report.basis;
    std::printf("PCA profile basis: rMax %.2f mm, %zu radii, fit %.2f s (K = %d)\n", b.rMax(), b.radii().size(),
                report.fitSeconds, b.K());
    std::printf("area-weighted relative L2 error of sum_k s_k b_k(r) vs the dipole R_d(r) on [0, rMax]\n");
    std::printf("held-out: %d random materials in the default range; presets: 10 Jensen presets x 3 channels\n\n",
                kHeldOutMaterials);
    std::printf("   K   held-out mean   held-out max   preset mean   preset max\n");
    for (const ErrorRow& r : report.rows)
        std::printf("  %2d   %13.3e   %12.3e   %11.3e   %10.3e\n", r.K, r.mean, r.max, r.presetMean, r.presetMax);
}

std::string errorCsv(const Report& report) {
    std::ostringstream csv;
    csv.precision(6);
    csv << "K,mean_error,max_error,preset_mean_error,preset_max_error\n";
    for (const ErrorRow& r : report.rows)
        csv << r.K << ',' << r.mean << ',' << r.max << ',' << r.presetMean << ',' << r.presetMax << '\n';
    return csv.str();
}

std::string reportJson(const Report& report) {
    nlohmann::json json;
    json["basis"] = nlohmann::json::array();
    for (const ErrorRow& r : report.rows)
        json["basis"].push_back({{"K", r.K},
                                 {"mean_error", r.mean},
                                 {"max_error", r.max},
                                 {"preset_mean_error", r.presetMean},
                                 {"preset_max_error", r.presetMax}});
    const auto eigenvalues = report.basis.eigenvalues();
    json["eigenvalues"] = std::vector<double>(eigenvalues.begin(), eigenvalues.end());
    json["r_max_mm"] = report.basis.rMax();
    json["radial_samples"] = report.basis.radii().size();
    json["held_out_materials"] = kHeldOutMaterials;
    json["fit_seconds"] = report.fitSeconds;
    return json.dump(2) + "\n";
}

// Left: b_1..b_4 over r (log axis). Right: the first 20 eigenvalues (log axis).
void drawFigure(const ProfileBasis& basis, const std::filesystem::path& path) {
    constexpr std::array<Color, 4> colors = {{{0.85f, 0.2f, 0.15f}, {0.15f, 0.45f, 0.85f}, {0.2f, 0.65f, 0.25f},
                                              {0.6f, 0.3f, 0.75f}}};
    Canvas canvas(1400, 600);
    const std::span<const double> radii = basis.radii().subspan(1);  // r_0 = 0 has no place on a log axis
    const auto firstFour = basis.values().first(4 * basis.radii().size());
    const double yMin = std::floor(std::min(0.0, *std::min_element(firstFour.begin(), firstFour.end())));
    const double yMax = std::ceil(*std::max_element(firstFour.begin(), firstFour.end()));
    std::vector<double> yTicks;
    const double step = yMax - yMin > 8.0 ? 2.0 : 1.0;
    for (double t = yMin; t <= yMax; t += step) yTicks.push_back(t);
    Axis x{radii.front(), radii.back(), true, decadeTicks(radii.front(), radii.back()), "r [mm]"};
    Axis y{yMin, yMax, false, yTicks, "b_k(r) [1/mm]"};
    Panel left(canvas, 110, 70, 660, 500, x, y);
    left.drawAxes("first four basis functions");
    for (int k = 0; k < 4; ++k) {
        std::vector<double> values(radii.size());
        for (std::size_t l = 0; l < radii.size(); ++l) values[l] = basis.evaluate(k, radii[l]);
        left.curve(radii, values, colors[k]);
        left.legend(k, "b" + std::to_string(k + 1), colors[k]);
    }

    const std::span<const double> eigenvalues = basis.eigenvalues();
    const double eigMin = std::pow(10.0, std::floor(std::log10(std::max(eigenvalues.back(), 1e-300))));
    Axis index{0.0, eigenvalues.size() + 1.0, false, {1, 4, 8, 12, 16, 20}, "index k"};
    Axis value{eigMin, 1.0, true, decadeTicks(eigMin, 1.0), "eigenvalue (fraction of training energy)"};
    Panel right(canvas, 820, 70, 1360, 500, index, value);
    right.drawAxes("eigenvalue spectrum");
    std::vector<double> ks(eigenvalues.size());
    for (std::size_t k = 0; k < ks.size(); ++k) ks[k] = k + 1.0;
    right.curve(ks, eigenvalues, {0.5f, 0.5f, 0.5f}, 1);
    for (std::size_t k = 0; k < ks.size(); ++k) right.marker(ks[k], eigenvalues[k], colors[1]);
    canvas.write(path);
}

int runBasis(int argc, char** argv) {
    CLI::App app{"Accuracy of the PCA profile basis over held-out materials and the Jensen presets", "opal-bench basis"};
    Options options;
    app.add_option("-o,--output", options.outputDir, "folder for basis_error.csv and basis.png")
        ->capture_default_str();
    app.add_option("--json", options.jsonFile, "also write the results as JSON to this file");
    app.add_option("--rmax", options.rMax, "basis radius in mm (0: the default for the range)")
        ->check(CLI::Range(0.0, 1e5))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try {
        ensureDirectory(options.outputDir);
        if (!options.jsonFile.empty()) ensureDirectory(options.jsonFile.parent_path().empty() ? "." : options.jsonFile.parent_path());
        const Report report = measure(options);
        printTable(report);
        writeFileAtomically(options.outputDir / "basis_error.csv", errorCsv(report));
        drawFigure(report.basis, options.outputDir / "basis.png");
        if (!options.jsonFile.empty()) writeFileAtomically(options.jsonFile, reportJson(report));
        std::printf("\nwrote %s and %s\n", (options.outputDir / "basis_error.csv").c_str(),
                    (options.outputDir / "basis.png").c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench basis: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace

Subcommand basisSubcommand() {
    return {"basis", "PCA profile basis error vs K over held-out materials and presets; Figure 2 plot", runBasis};
}

}  // namespace opal::bench
