// One RGB layer of an EXR that opal-render wrote, with its primId channel, for comparing
// two renders pixel by pixel (`opal-bench compare`). Layers are named as the AOV table
// names them (delegate/hd/aov.h): `subsurface` is subsurface.R/G/B, `color` the unprefixed
// R/G/B.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace opal::bench {

struct ExrLayer {
    std::string path;  // the file it was read from, for errors
    int width = 0, height = 0;
    std::vector<float> rgb;     // 3 per pixel, rows from the top
    std::vector<float> primId;  // 1 per pixel; -1 where nothing was hit
};

// Throws opal::Error naming the file for one that cannot be read, lacks the layer's three
// channels or primId.id.
ExrLayer readExrLayer(const std::string& path, const std::string& layer);

// 1 where both images show one of `ids` and the same one. Throws opal::Error naming both
// files when their sizes differ.
std::vector<std::uint8_t> primMask(const ExrLayer& a, const ExrLayer& b, const std::vector<int>& ids);

}  // namespace opal::bench
