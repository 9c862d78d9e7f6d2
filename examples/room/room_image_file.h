// Writes the room environment (room_environment.h) as a lat-long OpenEXR file of 32-bit
// float RGB, linear Rec.709 (a DomeLight's default colorSpace), atomically.
#pragma once

#include "examples/room/room_environment.h"

#include <filesystem>

namespace opal {

// Throws opal::Error naming the file (sizes as roomLatLong, OpenImageIO's errors).
void writeRoomImage(const std::filesystem::path& file, const RoomLook& look, int height);

}  // namespace opal
