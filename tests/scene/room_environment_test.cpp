// The candlelight scene's room (examples/room/room_environment.h) against its documented
// closed form: warm walls at the horizon, a darker floor and a dim ceiling beyond the
// blends, the same at every longitude, and the EXR reading back as computed.
#include "examples/room/room_environment.h"
#include "examples/room/room_image_file.h"
#include "schema/error.h"
#include "tests/scene/scene_test_files.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal {
namespace {

void expectNear(const Imath::V3f& a, const Imath::V3d& b, const char* where) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6) << where << " channel " << c;
}

double cosDegrees(double d) { return std::cos(d * std::numbers::pi / 180.0); }

TEST(RoomEnvironment, WallsFloorAndCeilingFollowTheDocumentedForm) {
    const RoomLook look;
    expectNear(roomRadiance(look, 0.0), Imath::V3d(look.wallColor), "horizon");
    expectNear(roomRadiance(look, -40.0), Imath::V3d(look.floorColor) * (look.floorLevel * cosDegrees(40.0)), "floor");
    expectNear(roomRadiance(look, 60.0), Imath::V3d(look.wallColor) * (look.ceilingLevel * cosDegrees(60.0)),
               "ceiling");
    // Warm everywhere, and the floor darker than the wall just above it.
    for (double e = -89.5; e < 90.0; e += 1.0) {
        const Imath::V3f v = roomRadiance(look, e);
        EXPECT_GT(v.x, v.y) << e;
        EXPECT_GT(v.y, v.z) << e;
        EXPECT_GT(v.z, 0.0f) << e;
    }
    EXPECT_LT(roomRadiance(look, look.floorEdge - look.blend).y, 0.5f * roomRadiance(look, 0.0).y);
}

TEST(RoomEnvironment, TheImageIsRowsOfTheRadianceFromTheTopAndReadsBack) {
    const test::SceneDir dir;
    const RoomLook look;
    const int height = 16;
    writeRoomImage(dir / "room.exr", look, height);
    auto in = OIIO::ImageInput::open((dir / "room.exr").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    ASSERT_EQ(in->spec().width, 2 * height);
    ASSERT_EQ(in->spec().height, height);
    ASSERT_EQ(in->spec().nchannels, 3);
    std::vector<float> rgb(std::size_t(2 * height * height * 3));
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data()));
    for (int row = 0; row < height; ++row) {
        const Imath::V3f expected = roomRadiance(look, 90.0 - 180.0 * (row + 0.5) / height);
        for (int column = 0; column < 2 * height; ++column)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(rgb[(std::size_t(row) * 2 * height + column) * 3 + c], expected[c]) << row << ", " << column;
    }
}

TEST(RoomEnvironment, ASizeThatIsNotTwoToOneIsAnError) {
    EXPECT_THROW(roomLatLong(RoomLook{}, 30, 16), Error);
    EXPECT_THROW(roomLatLong(RoomLook{}, 0, 0), Error);
}

}  // namespace
}  // namespace opal
