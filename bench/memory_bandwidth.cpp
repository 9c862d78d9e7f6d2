#include "bench/memory_bandwidth.h"

#include "delegate/hd/aov.h"
#include "delegate/relight/environment_vectors.h"
#include "delegate/relight/transfer_product.h"
#include "delegate/relight/vertex_gather.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace opal::bench {

double triadBandwidth(std::size_t elements, int repeats) {
    std::vector<double> a(elements, 0.0), b(elements, 1.0), c(elements, 2.0);
    const double s = 3.0;
    const auto triad = [&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, elements, 1 << 16), [&](const auto& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) a[i] = b[i] + s * c[i];
        });
    };
    triad();  // first touch: pages mapped before timing
    std::vector<double> rates;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        triad();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        rates.push_back(3.0 * sizeof(double) * double(elements) / seconds);
    }
    std::sort(rates.begin(), rates.end());
    return rates[rates.size() / 2];
}

StreamedBytes streamedBytes(const TranslucentAsset& asset, int width, int height) {
    const double n = double(asset.samples.size()), K = double(asset.basis.K());
    const bool dome = !asset.environment.offsets.empty();
    const double terms = dome ? double(asset.environment.fresnelTerms) : 2.0;
    const double lanes = 4.0 * std::ceil(3.0 * terms / 4.0);
    StreamedBytes bytes;
    bytes.light = double(TransferProduct(asset.transfer, asset.samples.size()).memoryBytes()) +
                  4.0 * n * lanes + 4.0 * n * K * 3.0 * terms;
    if (!asset.transfer.harmonics.empty()) {  // G read (3 x Q padded), the functions read twice
        const double Q = double(asset.transfer.harmonicSet.count);
        bytes.light += 4.0 * n * (3.0 * 4.0 * std::ceil(Q / 4.0) + 2.0 * Q);
    }
    bytes.environment =
        dome ? double(EnvironmentVectors(asset.environment, asset.samples.size()).memoryBytes()) + bytes.light : 0.0;
    const double vertices = double(asset.mesh.points.size());
    // The gather's weights, sample indices and visiting order as the engine lays them out
    // (16-bit indices up to 65,536 samples): its own count, not a copy of its layout.
    bytes.material = 4.0 * n * 3.0 * 4.0 * std::ceil(K / 4.0) + 4.0 * n * 3.0 +
                     double(VertexGather(asset.vertexWeights, asset.samples.size()).memoryBytes()) + 4.0 * vertices * 3.0;
    bytes.materialAfterLight = bytes.material;
    if (!asset.transfer.harmonics.empty())
        bytes.materialAfterLight += 4.0 * n * double(asset.transfer.harmonicSet.count) * 4.0 * std::ceil(K / 4.0);
    double channels = 0.0;
    for (const hd::AovDescriptor& aov : hd::aovTable()) channels += double(aov.channels.size());
    const double pixels = double(width) * double(height);
    bytes.pass = 2.0 * 4.0 * channels * pixels;
    bytes.colorPass = 2.0 * 4.0 * double(hd::aovDescriptor(hd::AovId::Color).channels.size()) * pixels;
    return bytes;
}

}  // namespace opal::bench
