#include "bench/compression_sweep.h"

#include <algorithm>

namespace opal::bench {

std::vector<TransferSettings> compressionSettings(std::span<const double> keeps, std::span<const double> energies) {
    const TransferSettings defaults;
    std::vector<TransferSettings> settings;
    const auto add = [&](double keep, double energy) {
        const bool seen = std::any_of(settings.begin(), settings.end(), [&](const TransferSettings& s) {
            return s.keepFraction == keep && s.energyFraction == energy;
        });
        if (!seen) settings.push_back({keep, energy});
    };
    for (double keep : keeps) add(keep, defaults.energyFraction);
    for (double energy : energies) add(defaults.keepFraction, energy);
    return settings;
}

BakeOptions sweepBakeOptions(const TranslucentAsset& asset, const std::string& mesh, const TransferSettings& transfer) {
    BakeOptions options;
    options.input = mesh;
    options.samples = asset.samples.size();
    options.unitsPerMm = asset.unitsPerMm;
    if (!asset.bake.scheme.empty()) options.scheme = asset.bake.scheme;
    options.level = asset.bake.level;
    options.seed = asset.bake.seed;
    options.visibility.terms = asset.bake.envTerms;
    if (!asset.environment.offsets.empty()) {
        options.visibility.cubeFaceSize = asset.environment.cubeFaceSize;
        options.visibility.fresnelTerms = asset.environment.fresnelTerms;
    }
    if (asset.basis.K() > 0) options.basisCount = asset.basis.K();
    options.range = asset.range;
    options.transfer = transfer;
    return options;
}

}  // namespace opal::bench
