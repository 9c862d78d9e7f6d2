// A dim, warm room as a lat-long environment (the candlelight scene's dome): warm walls
// around the horizon, a darker floor below and a dim ceiling above, the same in every
// direction around the vertical, as a room lit by one candle looks from its middle.
// Radiance depends on the elevation e (degrees, +90 up) only:
//   wall(e)  = 1 at the horizon, falling as cos(e) away from it (the candle lights the
//              walls at its height most),
//   floor    = floorLevel x wall below floorEdge, ceiling = ceilingLevel x wall above
//              ceilingEdge, each blended in over +-blend degrees (smoothstep),
// times a warm colour (linear Rec.709): wallColor on the walls and ceiling, floorColor on
// the floor. Row 0 is straight up (+Y, the dome's pole), the last row straight down;
// pixel centres sit at e = 90 - 180 (row + 0.5) / height.
#pragma once

#include <Imath/ImathVec.h>

#include <cstdint>
#include <vector>

namespace opal {

struct RoomLook {
    Imath::V3f wallColor{1.0f, 0.72f, 0.48f};   // warm plaster by candlelight
    Imath::V3f floorColor{0.9f, 0.6f, 0.38f};   // a wooden floor, redder
    float floorLevel = 0.3f;                    // the floor's brightness relative to the wall above it
    float ceilingLevel = 0.4f;
    float floorEdge = -10.0f;                   // degrees
    float ceilingEdge = 35.0f;
    float blend = 8.0f;
};

// The radiance in direction elevation `degrees`, RGB linear Rec.709.
Imath::V3f roomRadiance(const RoomLook& look, double degrees);

// The lat-long image, width x height RGB floats, row-major from the top. Throws
// opal::Error unless 1 <= height <= 16384 and width == 2 height.
std::vector<float> roomLatLong(const RoomLook& look, int width, int height);

}  // namespace opal
