// opal-render run as a process for the scene tests (its stdout and stderr kept in files of
// the test's folder), and an EXR's pixels read back, every channel, as floats.
#pragma once

#include "tests/scene/scene_test_files.h"

#include <OpenImageIO/imageio.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef OPAL_RENDER_EXECUTABLE
#error "tests/CMakeLists.txt must define OPAL_RENDER_EXECUTABLE for opal-test-scene"
#endif

namespace opal::scene {

struct ProcessResult {
    int exitCode = -1;
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline ProcessResult runOpalRender(const test::SceneDir& dir, const std::string& arguments) {
    const std::string command = std::string("'") + OPAL_RENDER_EXECUTABLE + "' " + arguments + " > '" +
                                (dir / "stdout.txt").string() + "' 2> '" + (dir / "stderr.txt").string() + "'";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stdout.txt"), slurp(dir / "stderr.txt")};
}

// The file's channel count; 0 when it does not read.
inline int exrChannelCount(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    return in ? in->spec().nchannels : 0;
}

// Every channel of every pixel, interleaved; empty when the file does not read.
inline std::vector<float> exrPixels(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) return {};
    return pixels;
}

}  // namespace opal::scene
