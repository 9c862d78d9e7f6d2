#include "bench/compression_sweep.h"

#include <algorithm>

namespace opal::bench {

// The smallest keep fraction opal-bake accepts: below the floor at any sample count.
constexpr double kCountOnlyKeep = 1e-6;

std::vector<TransferSettings> compressionSettings(std::span<const std::uint32_t> perRows,
                                                  std::span<const double> energies) {
    const TransferSettings defaults;
    std::vector<TransferSettings> settings;
    const auto add = [&](const TransferSettings& t) {
        const bool seen = std::any_of(settings.begin(), settings.end(), [&](const TransferSettings& s) {
            return s.keepFraction == t.keepFraction && s.energyFraction == t.energyFraction &&
                   s.minPerRow == t.minPerRow;
        });
        if (!seen) settings.push_back(t);
    };
    for (std::uint32_t perRow : perRows) add({kCountOnlyKeep, defaults.energyFraction, perRow});
    for (double energy : energies) add({defaults.keepFraction, energy, defaults.minPerRow});
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
