// The pixel probe, end to end: `probe X Y` prints every AOV's scene-linear value at the
// pixel, which must be what the saved EXR holds there (half floats for the filtered AOVs,
// floats for depth and primId), and the display value, which must be the saved PNG's.
#include "tests/view/exr_compare.h"

#include <sstream>

namespace opal::test {
namespace {

// "  subsurface R G B = 0.1 0.2 0.3" -> {"subsurface.R": 0.1, ...} ("color" is the EXR's R G B A).
std::map<std::string, double> probedValues(const std::string& out) {
    std::map<std::string, double> values;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t equals = line.find(" = ");
        if (line.rfind("  ", 0) != 0 || equals == std::string::npos) continue;
        std::istringstream names(line.substr(2, equals - 2)), numbers(line.substr(equals + 3));
        std::string aov, channel;
        names >> aov;
        if (aov == "display") names >> aov;  // "(color)"
        for (double value; names >> channel && numbers >> value;)
            values[(aov == "color" ? "" : aov.front() == '(' ? "display." : aov + ".") + channel] = value;
    }
    return values;
}

TEST(Probe, PrintsWhatTheSavedExrAndPngHoldAtThePixel) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("probe.script", "load " + scriptWord(asset) + "\nsave exr " + scriptWord(dir / "p.exr") + "\nsave png " +
                                  scriptWord(dir / "p.png") + "\nprobe 170 110\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 320x240 --script " + shellWord(dir / "probe.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    ASSERT_NE(run.out.find("probe 170 110\n"), std::string::npos) << run.out;
    const std::map<std::string, double> probed = probedValues(run.out);
    const ReadImage exr = readImage(dir / "p.exr");
    int compared = 0;
    for (int c = 0; c < exr.channels; ++c) {
        const auto value = probed.find(exr.names[c]);
        ASSERT_NE(value, probed.end()) << "the probe printed no " << exr.names[c] << ":\n" << run.out;
        const double saved = exr.at(170, 110, c);
        // The EXR holds the filtered AOVs as half floats: 11 significant bits.
        EXPECT_NEAR(value->second, saved, std::abs(saved) * 0x1p-10 + 1e-7) << exr.names[c];
        ++compared;
    }
    EXPECT_EQ(compared, 21);
    EXPECT_EQ(probed.at("primId.id"), 0.0) << "the pixel shows the sphere";
    EXPECT_GT(probed.at("subsurface.G"), 0.0);
    const ReadImage png = readImage(dir / "p.png");
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(probed.at(std::string("display.") + "RGB"[c]), png.at(170, 110, c), 0.5 / 255.0) << "RGB"[c];
}

}  // namespace
}  // namespace opal::test
