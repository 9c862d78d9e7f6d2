#include "delegate/output/exr_writer.h"

#include "color_test_support.h"
#include "delegate/output/color_config.h"
#include "schema/error.h"
#include "tests/support/restricted_child.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <map>

namespace opal {
namespace {

using test::TempDir;

constexpr int kWidth = 37;
constexpr int kHeight = 21;

Image filled(int channels, unsigned seed) {
    return test::randomSceneLinear(kWidth, kHeight, channels, seed, false);
}

Image depthImage() {
    Image depth(kWidth, kHeight, 1);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) depth.at(x, y, 0) = 1000.0f + 0.125f * x + 3.3f * y;
    }
    return depth;
}

Image primIdImage() {
    Image ids(kWidth, kHeight, 1);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x)
            ids.at(x, y, 0) = (x + y) % 5 == 0 ? -1.0f : 123456.0f + x + 100 * y;
    }
    return ids;
}

std::vector<AovLayer> frameLayers() {
    std::vector<AovLayer> layers;
    layers.push_back(makeAovLayer("color", filled(4, 1)));
    layers.push_back(makeAovLayer("subsurface", filled(3, 2)));
    layers.push_back(makeAovLayer("normal", filled(3, 3)));
    layers.push_back(makeAovLayer("depth", depthImage()));
    layers.push_back(makeAovLayer("primId", primIdImage()));
    return layers;
}

ColorSpaceIdentity shippedWorkingSpace() {
    return ColorConfig::fromFile(test::shippedConfig()).workingSpaceIdentity(nullptr);
}

const ExrMetadata kSettings = {
    {"samples", 16}, {"exposure", 1.5f}, {"camera", std::string("/cameras/main")}};

struct ReadBack {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;  // all channels, interleaved, as float

    int channel(const std::string& name) const { return spec.channelindex(name); }
    float at(int x, int y, const std::string& name) const {
        return pixels[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels +
                      channel(name)];
    }
};

ReadBack readExr(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    EXPECT_TRUE(in) << OIIO::geterror();
    ReadBack r{in->spec(), {}};
    r.pixels.resize(static_cast<std::size_t>(r.spec.width) * r.spec.height * r.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.pixels.data()));
    return r;
}

// Every channel of every layer, at half or float precision.
void expectPixels(const ReadBack& r, const std::vector<AovLayer>& layers, bool colorIsHalf) {
    for (const AovLayer& layer : layers) {
        const bool half = colorIsHalf && layer.format == hd::AovFormat::Float16;
        for (std::size_t c = 0; c < layer.channels.size(); ++c) {
            const std::string name = layer.exrChannelName(c);
            ASSERT_GE(r.channel(name), 0) << name;
            for (int y = 0; y < kHeight; ++y) {
                for (int x = 0; x < kWidth; ++x) {
                    const float written = layer.image.at(x, y, static_cast<int>(c));
                    const float tolerance = half ? std::abs(written) * 0x1p-11f + 1e-7f : 0.0f;
                    ASSERT_NEAR(r.at(x, y, name), written, tolerance)
                        << name << " " << x << "," << y;
                }
            }
        }
    }
}

TEST(ExrWriter, LayersChannelNamesAndFormatsReadBackThroughOpenImageIO) {
    TempDir dir;
    const std::vector<AovLayer> layers = frameLayers();
    writeExr(dir / "frame.exr", layers, shippedWorkingSpace(), kSettings, {}, nullptr);

    const ReadBack r = readExr(dir / "frame.exr");
    std::vector<std::string> names = r.spec.channelnames;
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "R", "depth.Z", "normal.X",
                                               "normal.Y", "normal.Z", "primId.id", "subsurface.B",
                                               "subsurface.G", "subsurface.R"}));
    for (int c = 0; c < r.spec.nchannels; ++c) {
        const std::string& name = r.spec.channelnames[c];
        const bool exact = name == "depth.Z" || name == "primId.id";
        EXPECT_EQ(r.spec.channelformat(c), exact ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF)
            << name;
    }
    expectPixels(r, layers, true);
    EXPECT_EQ(r.at(0, 0, "primId.id"), -1.0f);
    EXPECT_EQ(r.at(1, 0, "primId.id"), 123457.0f);
}

TEST(ExrWriter, HeaderCarriesColorSpaceAndRenderSettings) {
    TempDir dir;
    writeExr(dir / "frame.exr", frameLayers(), shippedWorkingSpace(), kSettings, {}, nullptr);
    const OIIO::ImageSpec spec = readExr(dir / "frame.exr").spec;

    const OIIO::ParamValue* chroma = spec.find_attribute("chromaticities");
    ASSERT_TRUE(chroma);
    ASSERT_EQ(chroma->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
    const float* xy = static_cast<const float*>(chroma->data());
    const float ap1[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
    for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(xy[i], ap1[i]) << i;

    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "ACEScg");
    EXPECT_EQ(spec.get_string_attribute("colorInteropID"), "lin_ap1_scene");
    EXPECT_EQ(spec.get_int_attribute("opal/samples"), 16);
    EXPECT_FLOAT_EQ(spec.get_float_attribute("opal/exposure"), 1.5f);
    EXPECT_EQ(spec.get_string_attribute("opal/camera"), "/cameras/main");
    EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
}

TEST(ExrWriter, FloatAndPizOnRequest) {
    TempDir dir;
    const std::vector<AovLayer> layers = frameLayers();
    writeExr(dir / "frame.exr", layers, shippedWorkingSpace(), {},
             {ExrPixelType::Float, ExrCompression::Piz}, nullptr);
    const ReadBack r = readExr(dir / "frame.exr");
    for (int c = 0; c < r.spec.nchannels; ++c)
        EXPECT_EQ(r.spec.channelformat(c), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(r.spec.get_string_attribute("compression"), "piz");
    expectPixels(r, layers, false);
}

TEST(ExrWriter, UnknownWorkingSpaceWritesTheNameOnlyAndWarns) {
    TempDir dir;
    std::vector<std::string> warnings;
    writeExr(dir / "frame.exr", frameLayers(), {"studio linear", std::nullopt, std::nullopt}, {},
             {}, &warnings);
    const OIIO::ImageSpec spec = readExr(dir / "frame.exr").spec;
    EXPECT_FALSE(spec.find_attribute("chromaticities"));
    EXPECT_FALSE(spec.find_attribute("colorInteropID"));
    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "studio linear");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("studio linear"), std::string::npos);
}

TEST(ExrWriter, UnwritableDirectoryThrowsWithThePathAndLeavesNothing) {
    TempDir dir;
    std::ofstream(dir / "not-a-directory") << "x";
    const std::filesystem::path target = dir / "not-a-directory/frame.exr";
    try {
        writeExr(target, frameLayers(), shippedWorkingSpace(), {}, {}, nullptr);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"not-a-directory"});
}

// Permissions do not bind root, and CI runs the tests as root: the write is tried by a
// child that has dropped to the user nobody (it fails before any image library runs).
TEST(ExrWriter, ReadOnlyDirectoryThrowsAndLeavesNothing) {
    TempDir dir;
    ::chmod(dir.path().c_str(), 0755);
    std::filesystem::create_directory(dir / "locked");
    ::chmod((dir / "locked").c_str(), 0555);
    const std::filesystem::path target = dir / "locked/frame.exr";
    const std::vector<AovLayer> layers = frameLayers();
    const ColorSpaceIdentity space = shippedWorkingSpace();
    const test::ChildReport r = test::unprivileged([&] {
        try {
            writeExr(target, layers, space, {}, {}, nullptr);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    });
    ASSERT_TRUE(r.ran) << r.text;
    EXPECT_NE(r.text.find(target.string()), std::string::npos) << r.text;
    EXPECT_NE(r.text.find("Permission denied"), std::string::npos) << r.text;
    EXPECT_TRUE(std::filesystem::is_empty(dir / "locked"));
}

// A file system that refuses more bytes halfway through the image (the process's file
// size limit: writes past it fail with EFBIG, as they fail with ENOSPC on a full disk;
// in-process, since the EXR library's threads would not survive a fork): the error names
// the file and the cause, and the previous file is intact.
TEST(ExrWriter, AWriteRefusedHalfwayKeepsThePreviousFileAndSaysWhy) {
    TempDir dir;
    const std::filesystem::path file = dir / "frame.exr";
    const std::vector<AovLayer> small = {makeAovLayer("color", filled(4, 1))};
    writeExr(file, small, shippedWorkingSpace(), {}, {ExrPixelType::Float, ExrCompression::Piz}, nullptr);
    const auto previous = std::filesystem::file_size(file);

    std::vector<AovLayer> big;
    big.push_back(makeAovLayer("color", test::randomSceneLinear(512, 512, 4, 7, false)));
    rlimit saved{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{previous + 4096, saved.rlim_max};
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
    std::string message = "(no error)";
    try {
        writeExr(file, big, shippedWorkingSpace(), {}, {ExrPixelType::Float, ExrCompression::Piz}, nullptr);
    } catch (const Error& e) {
        message = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, oldHandler);

    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame.exr"}) << "the temporary file is removed";
    expectPixels(readExr(file), small, false);
}

TEST(ExrWriter, InvalidAovDataLeavesThePreviousFileIntact) {
    TempDir dir;
    const std::filesystem::path file = dir / "frame.exr";
    const std::vector<AovLayer> good = frameLayers();
    writeExr(file, good, shippedWorkingSpace(), kSettings, {}, nullptr);

    std::vector<AovLayer> bad = frameLayers();
    bad.push_back(makeAovLayer("specular", Image(kWidth + 1, kHeight, 3)));
    try {
        writeExr(file, bad, shippedWorkingSpace(), kSettings, {}, nullptr);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(file.string()), std::string::npos) << message;
        EXPECT_NE(message.find("layer 'specular' is 38x21"), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame.exr"});
    expectPixels(readExr(file), good, true);
}

TEST(ExrWriter, DuplicateChannelsAreRejected) {
    TempDir dir;
    std::vector<AovLayer> layers;
    layers.push_back(makeAovLayer("color", filled(4, 1)));
    layers.push_back(makeAovLayer("alpha", filled(1, 2)));  // a second "A"
    EXPECT_THROW(writeExr(dir / "frame.exr", layers, shippedWorkingSpace(), {}, {}, nullptr),
                 Error);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace opal
