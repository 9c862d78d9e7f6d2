// `cmake --install` as a packager runs it, into a fresh prefix, then the installed programs
// alone as a pipeline runs them: an environment holding nothing of the build (env -i, a
// PATH of the prefix and the system), a small built-in mesh baked with opal-bake, a scene
// referencing it rendered by opal-render to EXR + PNG. The installed renderer must find the
// installed plugin and OCIO config (the EXR says which config), and no installed file,
// RUNPATH included, may name the build tree.
#include "tests/support/open_temp_dir.h"
#include "tests/support/scene_usda.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opal {
namespace {

namespace fs = std::filesystem;

struct ProcessRun {
    int exitCode = -1;
    std::string out, err;
};

std::string quoted(const std::string& text) { return "'" + text + "'"; }

// `command` through the shell in `dir`, its output kept in files there.
ProcessRun runIn(const fs::path& dir, const std::string& command) {
    const std::string line = "cd " + quoted(dir.string()) + " && " + command + " > run.out 2> run.err";
    const int status = std::system(line.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::fileContents(dir / "run.out"),
            test::fileContents(dir / "run.err")};
}

// An installed program run with nothing of the test's environment: no OPAL_PLUGINPATH,
// no OCIO, no LD_LIBRARY_PATH; found through PATH, as a user would run it.
ProcessRun runInstalled(const fs::path& prefix, const fs::path& dir, const std::string& arguments) {
    const std::string path = (prefix / OPAL_INSTALL_BINDIR).string() + ":/usr/bin:/bin";
    return runIn(dir, "env -i " + quoted("PATH=" + path) + " " + quoted("HOME=" + dir.string()) + " " + arguments);
}

bool mentions(const fs::path& file, const std::string& text) {
    return test::fileContents(file).find(text) != std::string::npos;
}

bool isElf(const fs::path& file) { return test::fileContents(file).starts_with("\x7f" "ELF"); }

// The wick (about 2.7 x 11.5 mm, 72.5-84 mm up) lit from the front, seen from 30 mm.
std::string wickScene() {
    using namespace test::usda;
    return header() + reference("Wick", "./wick.usda") + pointLight("Bulb", "2000", translate({0.6, 80, 20})) +
           camera("Camera", translate({0.6, 78, 30})) + renderSettings(48, 32);
}

class InstallTree : public ::testing::Test {
protected:
    void SetUp() override {
        const ProcessRun install = runIn(work.path(), quoted(OPAL_CMAKE_COMMAND) + " --install " + quoted(OPAL_BINARY_DIR) +
                                                   " --prefix " + quoted(prefix.string()));
        ASSERT_EQ(install.exitCode, 0) << install.out << install.err;
    }

    const test::OpenTempDir work;
    const fs::path prefix = work / "prefix";
    const fs::path bin = prefix / OPAL_INSTALL_BINDIR;
    const fs::path plugins = prefix / OPAL_INSTALL_LIBDIR / "opal" / "plugins";
    const fs::path data = prefix / OPAL_INSTALL_DATADIR / "opal";
};

TEST_F(InstallTree, HoldsEveryProgramThePluginTheColorConfigAndTheSchema) {
    std::vector<std::string> programs = {"opal-bake", "opal-bench", "opal-render", "opal-room"};
    if (OPAL_INSTALLS_VIEW) programs.push_back("opal-view");
    for (const std::string& program : programs) {
        EXPECT_TRUE(fs::is_regular_file(bin / program)) << program;
        const ProcessRun help = runInstalled(prefix, work.path(), program + " --help");
        EXPECT_EQ(help.exitCode, 0) << program << ": " << help.err;
    }
    for (const fs::path& file : {plugins / "plugInfo.json", plugins / "opalDelegate" / "plugInfo.json",
                                 plugins / "opalDelegate" / "opalDelegate.so", plugins / "opalPreview" / "plugInfo.json",
                                 plugins / "opalPreview" / "opalPreview.so", data / "ocio" / "config.ocio",
                                 data / "usd" / "plugInfo.json", data / "usd" / "generatedSchema.usda"})
        EXPECT_TRUE(fs::is_regular_file(file)) << file;
}

TEST_F(InstallTree, NamesNothingOfTheBuildTree) {
    const std::string build = fs::weakly_canonical(OPAL_BINARY_DIR).string();
    int files = 0, elves = 0;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(prefix)) {
        if (!entry.is_regular_file()) continue;
        ++files;
        EXPECT_FALSE(mentions(entry.path(), build)) << entry.path() << " names the build tree " << build;
        if (!isElf(entry.path())) continue;
        ++elves;
        const ProcessRun dynamic = runIn(work.path(), "readelf -d " + quoted(entry.path().string()));
        ASSERT_EQ(dynamic.exitCode, 0) << dynamic.err;
        std::istringstream lines(dynamic.out);
        for (std::string line; std::getline(lines, line);) {
            if (line.find("RUNPATH") == std::string::npos && line.find("RPATH") == std::string::npos) continue;
            EXPECT_EQ(line.find(build), std::string::npos) << entry.path() << ": " << line;
            EXPECT_EQ(line.find(OPAL_SOURCE_DIR), std::string::npos) << entry.path() << ": " << line;
        }
    }
    EXPECT_GE(files, 10);
    EXPECT_GE(elves, 5);  // four programs and the delegate at least
}

TEST_F(InstallTree, ListsTheInstalledDelegate) {
    const ProcessRun list = runInstalled(prefix, work.path(), "opal-render --list-delegates");
    ASSERT_EQ(list.exitCode, 0) << list.err;
    EXPECT_NE(list.out.find("OpalRendererPlugin"), std::string::npos) << list.out;
    EXPECT_NE(list.out.find("library: " + (plugins / "opalDelegate" / "opalDelegate.so").string()), std::string::npos)
        << list.out;
    EXPECT_NE(list.out.find("skipped: none"), std::string::npos) << list.out;
    // The preview delegate ships beside it, ranked after it.
    const std::size_t preview = list.out.find("OpalPreviewRendererPlugin\n    display name: Opal Preview\n    priority: 200");
    ASSERT_NE(preview, std::string::npos) << list.out;
    EXPECT_GT(preview, list.out.find("OpalRendererPlugin")) << list.out;
}

TEST_F(InstallTree, BakesAndRendersWithTheInstalledProgramsOnly) {
    const ProcessRun bake = runInstalled(prefix, work.path(), "opal-bake builtin:wick --samples 256 -o wick --quiet");
    ASSERT_EQ(bake.exitCode, 0) << bake.err;
    std::ofstream(work / "scene.usda") << wickScene();
    const ProcessRun render = runInstalled(prefix, work.path(), "opal-render scene.usda -o out.exr --preview out.png");
    ASSERT_EQ(render.exitCode, 0) << render.err;
    EXPECT_TRUE(fs::is_regular_file(work / "out.png"));

    auto in = OIIO::ImageInput::open((work / "out.exr").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    std::vector<std::string> channels(spec.channelnames.begin(), spec.channelnames.end());
    std::sort(channels.begin(), channels.end());
    const std::vector<std::string> expected = {
        "A",          "B",          "G",          "R",          "depth.Z",      "emission.B",   "emission.G",
        "emission.R", "irradiance.B", "irradiance.G", "irradiance.R", "normal.X", "normal.Y", "normal.Z",
        "primId.id", "specular.B", "specular.G", "specular.R", "subsurface.B", "subsurface.G", "subsurface.R"};
    EXPECT_EQ(channels, expected);
    EXPECT_EQ(spec.get_string_attribute("opal/delegate"), "Opal (OpalRendererPlugin)");
    EXPECT_EQ(spec.get_string_attribute("opal/colorConfig"), (data / "ocio" / "config.ocio").string());

    // The wick is in the frame and lit through its subsurface term.
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    const int alpha = spec.channelindex("A"), subsurface = spec.channelindex("subsurface.R");
    int covered = 0, lit = 0;
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
        covered += pixels[p * spec.nchannels + alpha] > 0.0f;
        lit += pixels[p * spec.nchannels + subsurface] > 0.0f;
    }
    EXPECT_GT(covered, 20);
    EXPECT_GT(lit, 0);
}

}  // namespace
}  // namespace opal
