// opal-room -o ROOM.exr [--height H]: the candlelight scene's dim, warm room as a lat-long
// environment image (room_environment.h), 2H x H pixels. Exit codes: 0 done, 1 error,
// 2 bad arguments.
#include "examples/room/room_image_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    CLI::App app{"opal-room: write the candlelight scene's room environment as a lat-long EXR"};
    std::string output;
    int height = 256;
    app.add_option("-o,--output", output, "the EXR to write")->required();
    app.add_option("--height", height, "rows (the image is twice as wide)")->check(CLI::Range(1, 16384))->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        opal::writeRoomImage(output, opal::RoomLook{}, height);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-room: error: %s\n", e.what());
        return 1;
    }
}
