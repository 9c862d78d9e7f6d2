#include "bench/cached_light.h"

#include "bake/light/light_bake.h"
#include "bake/light/light_spec.h"
#include "bench/output_folder.h"
#include "schema/asset/bake_id.h"
#include "schema/error.h"

#include <cstdio>
#include <fstream>

namespace opal::bench {

namespace fs = std::filesystem;

CachedLight bakeLightOrReuse(const std::string& spec, const fs::path& cacheDir, bool rebake) {
    ensureDirectory(cacheDir);
    CachedLight light;
    light.emitter = parseLightSpec(spec);
    const FieldSettings settings;
    const fs::path stem = cacheDir / ("light-" + formatBakeId(lightBakeIdentifier(light.emitter, settings)));
    const fs::path reportFile = fs::path(stem.string() + ".json");
    std::error_code ec;
    if (!rebake && fs::is_regular_file(reportFile, ec)) {
        try {
            std::ifstream in(reportFile);
            light.report = nlohmann::ordered_json::parse(in);
            light.sidecar = light.report.at("light").at("sidecar").get<std::string>();
            if (fs::is_regular_file(light.sidecar, ec)) {
                light.reused = true;
                return light;
            }
        } catch (const std::exception& e) {
            std::printf("  cached light %s unusable (%s): baking again\n", reportFile.c_str(), e.what());
        }
    }
    std::printf("  baking the light %s -> %s\n", spec.c_str(), stem.c_str());
    std::fflush(stdout);
    fs::remove(reportFile, ec);  // a bake killed midway leaves no report, so no stale reuse
    try {
        const LightBakeReport report = bakeLightAsset(spec, light.emitter, settings, stem, nullptr, CancelToken());
        for (const std::string& w : report.warnings) std::printf("  light bake warning: %s\n", w.c_str());
        writeLightBakeReport(reportFile, report);
        light.sidecar = report.sidecarFile;
        std::ifstream in(reportFile);
        light.report = nlohmann::ordered_json::parse(in);
    } catch (const std::exception& e) {
        throw Error("baking the light " + spec + " to " + stem.string() + ": " + e.what());
    }
    return light;
}

}  // namespace opal::bench
