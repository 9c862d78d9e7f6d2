#include "bench/cached_bake.h"

#include "bake/bake_identifier.h"
#include "bake/bake_report.h"
#include "bench/output_folder.h"
#include "schema/asset/asset_layer.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

namespace opal::bench {

namespace {

namespace fs = std::filesystem;

std::string numberText(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Every option that changes the baked asset, as one line.
std::string bakeKey(const BakeOptions& o) {
    std::ostringstream key;
    key << "input=" << o.input << " scheme=" << o.scheme << " level=" << (o.level ? std::to_string(*o.level) : "auto")
        << " samples=" << o.samples << " units_per_mm=" << numberText(o.unitsPerMm) << " material=" << o.material;
    if (o.range)
        key << " range=" << numberText(o.range->sigmaSPrimeMin) << ":" << numberText(o.range->sigmaSPrimeMax) << ","
            << numberText(o.range->sigmaAMin) << ":" << numberText(o.range->sigmaAMax) << ","
            << numberText(o.range->etaMin) << ":" << numberText(o.range->etaMax);
    return key.str() + "\n" + compressionIdentity(o);
}

std::string stemName(const BakeOptions& o, const std::string& name) {
    std::string stem = name + "-" + std::to_string(o.samples);
    const TransferSettings defaults;
    if (o.transfer.keepFraction != defaults.keepFraction || o.transfer.energyFraction != defaults.energyFraction ||
        o.transfer.minPerRow != defaults.minPerRow) {
        char buf[80];
        std::snprintf(buf, sizeof buf, "-k%g-m%u-e%g", o.transfer.keepFraction, o.transfer.minPerRow,
                      o.transfer.energyFraction);
        stem += buf;
    }
    return stem;
}

// The file's text, or nothing when it cannot be read.
std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return in ? std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()) : std::string();
}

}  // namespace

std::string bakeLabel(const std::string& input) {
    return input.rfind("builtin:", 0) == 0 ? input.substr(8) : fs::path(input).stem().string();
}

CachedBake bakeOrReuse(const BakeOptions& options, const std::string& name, const fs::path& cacheDir) {
    ensureDirectory(cacheDir);
    const fs::path stem = cacheDir / stemName(options, name);
    const fs::path layer = fs::path(stem.string() + ".usda"), keyFile = fs::path(stem.string() + ".key"),
                   reportFile = fs::path(stem.string() + ".bake.json");
    const std::string key = bakeKey(options);
    CachedBake bake;
    bake.layer = layer;
    std::error_code ec;
    if (readText(keyFile) == key && fs::is_regular_file(layer, ec)) {
        try {
            bake.report = nlohmann::ordered_json::parse(readText(reportFile));
            bake.asset = std::make_shared<const TranslucentAsset>(readAsset(layer));
            bake.reused = true;
            return bake;
        } catch (const std::exception& e) {
            std::printf("  cached bake %s unusable (%s): baking again\n", layer.c_str(), e.what());
        }
    }
    std::printf("  baking %s at %llu samples -> %s\n", options.input.c_str(), (unsigned long long)options.samples,
                layer.c_str());
    std::fflush(stdout);
    fs::remove(keyFile, ec);  // a bake killed midway leaves no key, so no stale reuse
    BakeReport report;
    try {
        auto asset = std::make_shared<const TranslucentAsset>(bakeAsset(options, nullptr, CancelToken(), &report));
        writeBakedAsset(stem, *asset, &report);
        writeBakeReport(reportFile, options, report);
        writeFileAtomically(keyFile, key);
        bake.asset = std::move(asset);
    } catch (const std::exception& e) {
        throw Error("baking " + options.input + " at " + std::to_string(options.samples) + " samples: " + e.what());
    }
    for (const std::string& w : report.warnings) std::printf("  bake warning: %s\n", w.c_str());
    bake.report = nlohmann::ordered_json::parse(readText(reportFile));
    return bake;
}

}  // namespace opal::bench
