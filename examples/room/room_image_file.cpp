#include "examples/room/room_image_file.h"

#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <OpenImageIO/imageio.h>

namespace opal {

void writeRoomImage(const std::filesystem::path& file, const RoomLook& look, int height) {
    const int width = 2 * height;
    const std::vector<float> rgb = roomLatLong(look, width, height);
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(temporary.string());
        if (!out) throw Error("OpenImageIO cannot write it: " + OIIO::geterror());
        OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
        spec.attribute("compression", "zip");
        if (!out->open(temporary.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) ||
            !out->close())
            throw Error("OpenImageIO: " + out->geterror());
    });
}

}  // namespace opal
