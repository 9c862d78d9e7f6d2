#include "delegate/output/aov_layer.h"

#include "schema/error.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

std::vector<std::string> exrNames(const AovLayer& layer) {
    std::vector<std::string> names;
    for (std::size_t c = 0; c < layer.channels.size(); ++c)
        names.push_back(layer.exrChannelName(c));
    return names;
}

TEST(AovLayer, StandardChannelNames) {
    using V = std::vector<std::string>;
    EXPECT_EQ(exrNames(makeAovLayer("color", Image(2, 2, 4))), (V{"R", "G", "B", "A"}));
    EXPECT_EQ(exrNames(makeAovLayer("color", Image(2, 2, 3))), (V{"R", "G", "B"}));
    EXPECT_EQ(exrNames(makeAovLayer("subsurface", Image(2, 2, 3))),
              (V{"subsurface.R", "subsurface.G", "subsurface.B"}));
    EXPECT_EQ(exrNames(makeAovLayer("specular", Image(2, 2, 3))),
              (V{"specular.R", "specular.G", "specular.B"}));
    EXPECT_EQ(exrNames(makeAovLayer("irradiance", Image(2, 2, 3))),
              (V{"irradiance.R", "irradiance.G", "irradiance.B"}));
    EXPECT_EQ(exrNames(makeAovLayer("normal", Image(2, 2, 3))),
              (V{"normal.X", "normal.Y", "normal.Z"}));
    EXPECT_EQ(exrNames(makeAovLayer("depth", Image(2, 2, 1))), (V{"depth.Z"}));
    EXPECT_EQ(exrNames(makeAovLayer("primId", Image(2, 2, 1))), (V{"primId.id"}));
    EXPECT_EQ(exrNames(makeAovLayer("alpha", Image(2, 2, 1))), (V{"A"}));
}

TEST(AovLayer, DepthAndIdsAreStoredExactly) {
    EXPECT_EQ(makeAovLayer("depth", Image(1, 1, 1)).format, hd::AovFormat::Float32);
    EXPECT_EQ(makeAovLayer("primId", Image(1, 1, 1)).format, hd::AovFormat::Float32);
    EXPECT_EQ(makeAovLayer("color", Image(1, 1, 4)).format, hd::AovFormat::Float16);
}

TEST(AovLayer, UnknownNameListsTheKnownOnes) {
    try {
        makeAovLayer("diffuse", Image(1, 1, 3));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "color, subsurface, specular, emission, irradiance, normal, depth, primId, alpha"),
                  std::string::npos)
            << e.what();
    }
}

TEST(AovLayer, WrongChannelCountIsAnError) {
    EXPECT_THROW(makeAovLayer("depth", Image(1, 1, 3)), Error);
    EXPECT_THROW(makeAovLayer("normal", Image(1, 1, 4)), Error);
    EXPECT_THROW(makeAovLayer("color", Image(1, 1, 2)), Error);
}

}  // namespace
}  // namespace opal
