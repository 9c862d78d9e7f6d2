#include "bench/mean_free_path_ends.h"

#include "schema/error.h"

#include <string>

namespace opal::bench {

namespace {

Material corner(const EditableRange& range, double sigmaSPrime, double sigmaA, double eta) {
    range.validate("editable range");
    if (!(eta >= range.etaMin && eta <= range.etaMax))
        throw Error("editable range: eta " + std::to_string(eta) + " lies outside [" + std::to_string(range.etaMin) +
                    ", " + std::to_string(range.etaMax) + "]");
    return {Rgb{sigmaSPrime, sigmaSPrime, sigmaSPrime}, Rgb{sigmaA, sigmaA, sigmaA}, eta};
}

}  // namespace

Rgb meanFreePath(const Material& material) {
    Rgb ell;
    for (int c = 0; c < 3; ++c) ell[c] = 1.0 / (material.sigmaSPrime[c] + material.sigmaA[c]);
    return ell;
}

Material shortestMeanFreePath(const EditableRange& range, double eta) {
    return corner(range, range.sigmaSPrimeMax, range.sigmaAMax, eta);
}

Material longestMeanFreePath(const EditableRange& range, double eta) {
    return corner(range, range.sigmaSPrimeMin, range.sigmaAMin, eta);
}

Material materialNamed(const std::string& name, const TranslucentAsset& asset) {
    const Material& byDefault = asset.defaultMaterial;
    if (name == "short") return shortestMeanFreePath(asset.range, byDefault.eta);
    if (name == "long") return longestMeanFreePath(asset.range, byDefault.eta);
    return byDefault;
}

}  // namespace opal::bench
