#include "bake/light/cube_map_compression.h"

#include "schema/wavelet/haar.h"

#include <algorithm>

namespace opal {

CompressedCubeMap compressCubeMap(std::vector<float>& rgb, const CubeMapLayout& layout, double keptEnergy) {
    haarForwardCharts<float>(rgb, layout.charts(), 3);
    CompressedCubeMap out;
    const std::uint32_t n = layout.texels();
    std::vector<double> energy(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) energy[i] += double(rgb[3 * i + c]) * rgb[3 * i + c];
        out.energy += energy[i];
    }
    if (out.energy == 0.0) return out;
    std::vector<std::uint32_t> order;  // the nonzero coefficients (most are zero), largest first
    for (std::uint32_t i = 0; i < n; ++i)
        if (energy[i] > 0.0) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return energy[a] != energy[b] ? energy[a] > energy[b] : a < b;
    });
    double kept = 0.0;
    std::size_t count = 0;
    while (count < order.size() && kept < keptEnergy * out.energy) kept += energy[order[count++]];
    for (std::size_t k = count; k < order.size(); ++k) out.droppedEnergy += energy[order[k]];
    out.indices.assign(order.begin(), order.begin() + std::ptrdiff_t(count));
    std::sort(out.indices.begin(), out.indices.end());
    for (std::uint32_t i : out.indices) out.values.insert(out.values.end(), {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
    return out;
}

}  // namespace opal
