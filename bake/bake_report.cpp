#include "bake/bake_report.h"

#include "schema/usd/atomic_file.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <charconv>
#include <cstdio>
#include <sstream>

namespace opal {

namespace {

nlohmann::ordered_json optionsJson(const BakeOptions& o) {
    return {{"input", o.input},
            {"scheme", o.scheme},
            {"level", o.level ? nlohmann::ordered_json(*o.level) : nlohmann::ordered_json("auto")},
            {"samples", o.samples},
            {"units_per_mm", o.unitsPerMm},
            {"material", o.material},
            {"basis", o.basisCount},
            {"keep", o.transfer.keepFraction},
            {"keep_min", o.transfer.minPerRow},
            {"energy", o.transfer.energyFraction},
            {"env_res", o.visibility.cubeFaceSize},
            {"env_terms", o.visibility.terms},
            {"env_error", o.visibility.error},
            {"seed", o.seed}};
}

double parseNumber(std::string_view text, const std::string& part) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        throw Error("'" + part + "': '" + std::string(text) + "' is not a number");
    return v;
}

// A farm bake's tasks per stage (bake/farm/task_stats.h).
nlohmann::ordered_json farmJson(const BakeReport& r) {
    nlohmann::ordered_json stages = nlohmann::ordered_json::array();
    for (const StageTasks& s : r.farmStages)
        stages.push_back({{"stage", s.stage},
                          {"tasks", s.tasks},
                          {"measured", s.measured},
                          {"seconds_max", s.secondsMax},
                          {"seconds_total", s.secondsTotal},
                          {"peak_rss_bytes", s.peakRssBytes}});
    return {{"shards", r.farmShards}, {"stages", stages}};
}

}  // namespace

void writeBakeReport(const std::filesystem::path& path, const BakeOptions& options, const BakeReport& r) {
    nlohmann::ordered_json j;
    j["samples"] = r.samples;
    j["charts"] = r.charts;
    j["grid"] = r.grid;
    j["subdivision_level"] = r.subdivisionLevel;
    j["render_vertices"] = r.renderVertices;
    j["raw_bytes"] = r.transfer.rawBytes;
    j["step1_bytes"] = r.transfer.step1Bytes;
    j["step1_per_row"] = r.transfer.step1PerRow;
    j["step1_budget"] = r.transfer.step1Floor ? "keep_min: keep x samples is fewer" : "keep x samples";
    j["step2_bytes"] = r.transfer.step2Bytes;
    j["sidecar_bytes"] = r.sidecarBytes;
    j["sidecar_file"] = r.sidecarFile.string();
    j["compression_ratio"] = r.sidecarBytes ? double(r.transfer.rawBytes) / double(r.sidecarBytes) : 0.0;
    j["energy_kept"] = r.transfer.energyKept;
    j["transfer_rel_rmse"] = r.transferRelRmse;
    nlohmann::ordered_json seconds = nlohmann::ordered_json::object();
    double total = 0.0;
    for (const auto& [stage, s] : r.seconds) {
        seconds[stage] = s;
        total += s;
    }
    seconds["total"] = total;
    j["seconds"] = seconds;
    j["peak_rss_bytes"] = r.peakRssBytes;
    if (r.farmShards) j["farm"] = farmJson(r);
    j["warnings"] = r.warnings;
    j["options"] = optionsJson(options);
    const std::string text = j.dump(2) + "\n";
    AtomicFileWriter out(path);
    out.append(std::as_bytes(std::span(text)));
    out.commit();
}

std::string formatBakeSummary(const std::filesystem::path& stem, const BakeReport& r) {
    const auto mib = [](std::uint64_t b) { return double(b) / (1024.0 * 1024.0); };
    double total = 0.0;
    for (const auto& [stage, s] : r.seconds) total += s;
    char buf[1024];
    std::snprintf(buf, sizeof buf,
                  "opal-bake: wrote %s.usda and %s\n"
                  "  samples %llu (%u charts of %ux%u), render vertices %llu\n"
                  "  transfer  raw %.1f MiB | step 1 (Haar, %.0f per row%s) %.1f MiB | step 2 (CDF 9/7) %.1f MiB | sidecar %.1f MiB\n"
                  "  compression %.0fx, energy kept %.6f, transfer rel. RMSE %.4f\n"
                  "  %.1f s, peak memory %.0f MiB\n",
                  stem.string().c_str(), r.sidecarFile.string().c_str(), (unsigned long long)r.samples, r.charts, r.grid,
                  r.grid, (unsigned long long)r.renderVertices, mib(r.transfer.rawBytes), r.transfer.step1PerRow,
                  r.transfer.step1Floor ? ": the --keep-min floor" : "", mib(r.transfer.step1Bytes),
                  mib(r.transfer.step2Bytes), mib(r.sidecarBytes),
                  r.sidecarBytes ? double(r.transfer.rawBytes) / double(r.sidecarBytes) : 0.0, r.transfer.energyKept,
                  r.transferRelRmse, total, mib(r.peakRssBytes));
    return buf;
}

EditableRange parseEditableRange(const std::string& text) {
    EditableRange range = EditableRange::coveringPresets();
    std::stringstream parts(text);
    std::string part;
    while (std::getline(parts, part, ',')) {
        const auto eq = part.find('='), colon = part.find(':');
        if (eq == std::string::npos || colon == std::string::npos || colon < eq)
            throw Error("'" + part + "': expected NAME=MIN:MAX");
        const std::string name = part.substr(0, eq);
        const double lo = parseNumber(std::string_view(part).substr(eq + 1, colon - eq - 1), part);
        const double hi = parseNumber(std::string_view(part).substr(colon + 1), part);
        if (name == "sigmaS") range.sigmaSPrimeMin = lo, range.sigmaSPrimeMax = hi;
        else if (name == "sigmaA") range.sigmaAMin = lo, range.sigmaAMax = hi;
        else if (name == "eta") range.etaMin = lo, range.etaMax = hi;
        else throw Error("'" + part + "': unknown parameter '" + name + "' (sigmaS, sigmaA or eta)");
    }
    range.validate("editable range");  // the caller names the option
    return range;
}

std::uint64_t peakRssBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

}  // namespace opal
