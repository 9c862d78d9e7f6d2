#include "bench/exr_layer.h"

#include "schema/error.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <string>

namespace opal::bench {

ExrLayer readExrLayer(const std::string& path, const std::string& layer) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw Error(path + ": cannot open: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const std::string prefix = layer == "color" ? "" : layer + ".";
    std::array<int, 3> rgb{};
    for (int c = 0; c < 3; ++c) {
        const std::string name = prefix + "RGB"[c];
        rgb[c] = spec.channelindex(name);
        if (rgb[c] < 0) throw Error(path + ": no channel " + name + " (is it an opal-render EXR with that AOV?)");
    }
    const int id = spec.channelindex("primId.id");
    if (id < 0) throw Error(path + ": no channel primId.id (render it with the primId AOV)");
    std::vector<float> all(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw Error(path + ": cannot read its pixels: " + in->geterror());
    ExrLayer out{path, spec.width, spec.height, {}, {}};
    const std::size_t pixels = std::size_t(spec.width) * spec.height;
    out.rgb.resize(3 * pixels);
    out.primId.resize(pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        const float* px = &all[p * spec.nchannels];
        for (int c = 0; c < 3; ++c) out.rgb[3 * p + c] = px[rgb[c]];
        out.primId[p] = px[id];
    }
    return out;
}

std::vector<std::uint8_t> primMask(const ExrLayer& a, const ExrLayer& b, const std::vector<int>& ids) {
    const auto chosen = [&](float id) {
        return id >= 0.0f && id < 2e9f && std::find(ids.begin(), ids.end(), int(id)) != ids.end();
    };
    if (a.width != b.width || a.height != b.height)
        throw Error(b.path + ": " + std::to_string(b.width) + "x" + std::to_string(b.height) + ", but " + a.path +
                    " is " + std::to_string(a.width) + "x" + std::to_string(a.height));
    std::vector<std::uint8_t> mask(a.primId.size());
    for (std::size_t p = 0; p < mask.size(); ++p) mask[p] = chosen(a.primId[p]) && a.primId[p] == b.primId[p];
    return mask;
}

}  // namespace opal::bench
