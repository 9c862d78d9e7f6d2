#include "delegate/output/exr_writer.h"

#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <list>
#include <set>

namespace opal {
namespace {

std::string sizeOf(const Image& image) {
    return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

void validateLayer(const AovLayer& layer, const AovLayer& first, std::set<std::string>& names) {
    const std::string where = "layer '" + layer.name + "'";
    if (layer.image.empty()) throw Error(where + ": has no pixels");
    if (static_cast<std::size_t>(layer.image.channels()) != layer.channels.size()) {
        throw Error(where + ": image has " + std::to_string(layer.image.channels()) +
                    " channels but " + std::to_string(layer.channels.size()) + " channel names");
    }
    if (layer.image.width() != first.image.width() ||
        layer.image.height() != first.image.height()) {
        throw Error(where + " is " + sizeOf(layer.image) + " but layer '" + first.name + "' is " +
                    sizeOf(first.image));
    }
    for (std::size_t c = 0; c < layer.channels.size(); ++c) {
        if (layer.channels[c].empty())
            throw Error(where + ": channel " + std::to_string(c) + " has no name");
        if (!names.insert(layer.exrChannelName(c)).second) {
            throw Error(where + ": channel '" + layer.exrChannelName(c) + "' is written twice");
        }
    }
}

void validateMetadata(const ExrMetadata& metadata) {
    std::set<std::string> keys;
    for (const auto& [key, value] : metadata) {
        if (key.empty()) throw Error("render setting with an empty name");
        if (!keys.insert(key).second) throw Error("render setting '" + key + "' given twice");
    }
}

void validate(std::span<const AovLayer> layers, const ExrMetadata& metadata) {
    if (layers.empty()) throw Error("no AOV layers to write");
    std::set<std::string> names;
    for (const AovLayer& layer : layers) validateLayer(layer, layers.front(), names);
    validateMetadata(metadata);
}

Imf::PixelType pixelType(const AovLayer& layer, const ExrOptions& options) {
    if (layer.format == hd::AovFormat::Float32) return Imf::FLOAT;
    return options.colorPixelType == ExrPixelType::Half ? Imf::HALF : Imf::FLOAT;
}

Imf::Chromaticities toImf(const Chromaticities& c) {
    auto v = [](Chromaticities::Xy xy) { return Imath::V2f(float(xy.x), float(xy.y)); };
    return Imf::Chromaticities(v(c.red), v(c.green), v(c.blue), v(c.white));
}

void addColorSpace(Imf::Header& header, const ColorSpaceIdentity& colorSpace) {
    if (colorSpace.chromaticities)
        Imf::addChromaticities(header, toImf(*colorSpace.chromaticities));
    header.insert("oiio:ColorSpace", Imf::StringAttribute(colorSpace.name));
    if (colorSpace.interopId)
        header.insert("colorInteropID", Imf::StringAttribute(*colorSpace.interopId));
}

Imf::StringAttribute attributeOf(const std::string& s) { return Imf::StringAttribute(s); }
Imf::FloatAttribute attributeOf(float f) { return Imf::FloatAttribute(f); }
Imf::IntAttribute attributeOf(int i) { return Imf::IntAttribute(i); }

void addMetadata(Imf::Header& header, const ExrMetadata& metadata) {
    for (const auto& [key, value] : metadata) {
        const std::string name = "opal/" + key;
        std::visit([&](const auto& v) { header.insert(name, attributeOf(v)); }, value);
    }
}

Imf::Header makeHeader(std::span<const AovLayer> layers, const ColorSpaceIdentity& colorSpace,
                       const ExrMetadata& metadata, const ExrOptions& options) {
    const Image& first = layers.front().image;
    Imf::Header header(first.width(), first.height());
    header.compression() =
        options.compression == ExrCompression::Zip ? Imf::ZIP_COMPRESSION : Imf::PIZ_COMPRESSION;
    for (const AovLayer& layer : layers) {
        for (std::size_t c = 0; c < layer.channels.size(); ++c) {
            header.channels().insert(layer.exrChannelName(c),
                                     Imf::Channel(pixelType(layer, options)));
        }
    }
    addColorSpace(header, colorSpace);
    addMetadata(header, metadata);
    return header;
}

// Slices of the caller's float images, plus half copies for half channels (OpenEXR does
// not convert on output; the copies live as long as the frame buffer).
class ExrFrameBuffer {
public:
    ExrFrameBuffer(std::span<const AovLayer> layers, const ExrOptions& options) {
        for (const AovLayer& layer : layers) {
            for (std::size_t c = 0; c < layer.channels.size(); ++c) {
                pixelType(layer, options) == Imf::HALF ? addHalf(layer, c) : addFloat(layer, c);
            }
        }
    }
    const Imf::FrameBuffer& get() const { return buffer_; }

private:
    void addFloat(const AovLayer& layer, std::size_t c) {
        const Image& image = layer.image;
        char* base = reinterpret_cast<char*>(const_cast<float*>(image.row(0) + c));
        buffer_.insert(layer.exrChannelName(c),
                       Imf::Slice(Imf::FLOAT, base, sizeof(float) * image.channels(),
                                  sizeof(float) * image.rowFloats()));
    }
    void addHalf(const AovLayer& layer, std::size_t c) {
        const Image& image = layer.image;
        std::vector<Imath::half>& plane = halfPlanes_.emplace_back();
        plane.reserve(static_cast<std::size_t>(image.width()) * image.height());
        for (std::size_t i = c; i < image.pixels().size(); i += image.channels()) {
            plane.emplace_back(image.pixels()[i]);
        }
        buffer_.insert(layer.exrChannelName(c),
                       Imf::Slice(Imf::HALF, reinterpret_cast<char*>(plane.data()),
                                  sizeof(Imath::half), sizeof(Imath::half) * image.width()));
    }

    Imf::FrameBuffer buffer_;
    std::list<std::vector<Imath::half>> halfPlanes_;  // a list: planes never move
};

void writeFile(const std::filesystem::path& file, const Imf::Header& header,
               const ExrFrameBuffer& pixels) {
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(pixels.get());
    out.writePixels(header.dataWindow().max.y - header.dataWindow().min.y + 1);
}

}  // namespace

void writeExr(const std::filesystem::path& file, std::span<const AovLayer> layers,
              const ColorSpaceIdentity& colorSpace, const ExrMetadata& metadata,
              const ExrOptions& options, std::vector<std::string>* warnings) {
    try {
        validate(layers, metadata);
    } catch (const Error& e) {
        throw Error(file.string() + ": " + e.what());
    }
    if (!colorSpace.chromaticities && warnings) {
        warnings->push_back(file.string() + ": no chromaticities written: color space '" +
                            colorSpace.name + "' has no known primaries");
    }
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        writeFile(temporary, makeHeader(layers, colorSpace, metadata, options),
                  ExrFrameBuffer(layers, options));
    });
}

}  // namespace opal
