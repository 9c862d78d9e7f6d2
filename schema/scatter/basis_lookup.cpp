#include "schema/error.h"
#include "schema/scatter/profile_basis.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

// Row i of the table holds b_k(rMax (i / resolution)^2) for every k: uniform in
// u = sqrt(r / rMax), so the samples are dense near r = 0 where the profiles peak.
BasisLookup::BasisLookup(const ProfileBasis& basis, int resolution)
    : K_(basis.K()), resolution_(resolution), rMax_(static_cast<float>(basis.rMax())) {
    if (resolution < 1) throw Error("BasisLookup: resolution = " + std::to_string(resolution) + " must be >= 1");
    if (K_ < 1 || !(basis.rMax() > 0.0)) throw Error("BasisLookup: the profile basis is empty");
    scale_ = static_cast<float>(resolution / std::sqrt(basis.rMax()));
    table_.resize(static_cast<std::size_t>(resolution + 1) * K_);
    for (int i = 0; i <= resolution; ++i) {
        const double u = static_cast<double>(i) / resolution;
        const double r = std::min(basis.rMax() * u * u, basis.rMax());
        for (int k = 0; k < K_; ++k) table_[static_cast<std::size_t>(i) * K_ + k] = static_cast<float>(basis.evaluate(k, r));
    }
}

void BasisLookup::evaluate(float r, float* out) const {
    const float x = std::sqrt(r) * scale_;  // u * resolution; NaN for r < 0
    if (!(x <= static_cast<float>(resolution_))) {
        std::fill_n(out, K_, 0.0f);
        return;
    }
    const int i = std::min(static_cast<int>(x), resolution_ - 1);
    const float t = x - static_cast<float>(i);
    const float* lo = table_.data() + static_cast<std::size_t>(i) * K_;
    const float* hi = lo + K_;
    for (int k = 0; k < K_; ++k) out[k] = lo[k] + t * (hi[k] - lo[k]);
}

}  // namespace opal
