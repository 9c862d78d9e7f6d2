// What the end-to-end viewer tests share: opal-view run as a process (on the X display the
// test runs under), and images it wrote read back with OpenImageIO.
#pragma once

#include "tests/scene/scene_test_files.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opal::test {

struct ViewRun {
    int exitCode = -1;
    std::string out, err;
};

inline std::string slurpFile(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// A path as one word of a shell command line, and of an opal-view script.
// (Appended, not `"'" + path.string() + "'"`: GCC 12 warns falsely on that concatenation.)
inline std::string quotedWord(const std::filesystem::path& path, char quote) {
    std::string word(1, quote);
    word += path.string();
    word += quote;
    return word;
}
inline std::string shellWord(const std::filesystem::path& path) { return quotedWord(path, '\''); }
inline std::string scriptWord(const std::filesystem::path& path) { return quotedWord(path, '"'); }

// The script line that saves the EXR dir/name.
inline std::string saveExr(const SceneDir& dir, const std::string& name) { return "save exr " + scriptWord(dir / name) + "\n"; }

// EXECUTABLE ARGUMENTS, output captured in `dir`.
// `environment`: assignments put before the command ("NAME=VALUE ").
inline ViewRun runProgram(const char* executable, const SceneDir& dir, const std::string& arguments,
                          const std::string& environment = "") {
    const std::string command = environment + "'" + executable + "' " + arguments + " > '" +
                                (dir / "view-out.txt").string() + "' 2> '" + (dir / "view-err.txt").string() + "'";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurpFile(dir / "view-out.txt"),
            slurpFile(dir / "view-err.txt")};
}

// Its list of recent files goes to `dir`/config (XDG_CONFIG_HOME), never the user's.
inline ViewRun runOpalView(const SceneDir& dir, const std::string& arguments) {
    return runProgram(OPAL_VIEW_EXECUTABLE, dir, arguments, "XDG_CONFIG_HOME=" + shellWord(dir / "config") + " ");
}

inline ViewRun runOpalRender(const SceneDir& dir, const std::string& arguments) {
    return runProgram(OPAL_RENDER_EXECUTABLE, dir, arguments);
}

// An image as float channels, with the channel names the file gives.
struct ReadImage {
    int width = 0, height = 0, channels = 0;
    std::vector<std::string> names;
    std::vector<float> pixels;

    int channel(const std::string& name) const {
        for (int c = 0; c < channels; ++c)
            if (names[c] == name) return c;
        ADD_FAILURE() << "no channel " << name;
        return 0;
    }
    float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

inline ReadImage readImage(const std::filesystem::path& file) {
    ReadImage image;
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        ADD_FAILURE() << "cannot read " << file << ": " << OIIO::geterror();
        return image;
    }
    const OIIO::ImageSpec& spec = in->spec();
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.names.assign(spec.channelnames.begin(), spec.channelnames.end());
    image.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        ADD_FAILURE() << "cannot read the pixels of " << file;
    return image;
}

}  // namespace opal::test
