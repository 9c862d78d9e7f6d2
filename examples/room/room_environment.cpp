#include "examples/room/room_environment.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace opal {

namespace {

// 0 below edge - blend, 1 above edge + blend, smooth in between.
double smoothstep(double edge, double blend, double x) {
    const double t = std::clamp((x - (edge - blend)) / (2.0 * blend), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

Imath::V3f roomRadiance(const RoomLook& look, double degrees) {
    const double wall = std::cos(degrees * std::numbers::pi / 180.0);
    const double aboveFloor = smoothstep(look.floorEdge, look.blend, degrees);
    const double ceiling = smoothstep(look.ceilingEdge, look.blend, degrees);
    const double wallLevel = 1.0 + (double(look.ceilingLevel) - 1.0) * ceiling;
    const Imath::V3d wallPart = Imath::V3d(look.wallColor) * (wall * wallLevel * aboveFloor);
    const Imath::V3d floorPart = Imath::V3d(look.floorColor) * (wall * look.floorLevel * (1.0 - aboveFloor));
    const Imath::V3d rgb = wallPart + floorPart;
    return Imath::V3f(float(rgb.x), float(rgb.y), float(rgb.z));
}

std::vector<float> roomLatLong(const RoomLook& look, int width, int height) {
    if (height < 1 || height > 16384 || width != 2 * height)
        throw Error("room environment: " + std::to_string(width) + " x " + std::to_string(height) +
                    " pixels; a lat-long image is twice as wide as it is high, 1 to 16384 rows");
    std::vector<float> rgb(std::size_t(width) * std::size_t(height) * 3);
    for (int row = 0; row < height; ++row) {
        const Imath::V3f value = roomRadiance(look, 90.0 - 180.0 * (row + 0.5) / height);
        for (int column = 0; column < width; ++column) {
            float* pixel = &rgb[(std::size_t(row) * width + column) * 3];
            pixel[0] = value.x;
            pixel[1] = value.y;
            pixel[2] = value.z;
        }
    }
    return rgb;
}

}  // namespace opal
