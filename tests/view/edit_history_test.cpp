// Undo and redo, end to end: an edit undone gives back the picture from before it, byte
// for byte in the saved EXR, and redo the edited one; a disabled light leaves the asset
// unlit and enabling it again restores the picture; lights added, renamed and removed.
#include "tests/view/exr_compare.h"

#include <iostream>

namespace opal::test {
namespace {


TEST(EditHistory, UndoGivesBackThePictureBeforeTheEditAndRedoTheEditedOne) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("undo.script", "load " + scriptWord(asset) + "\n" + saveExr(dir, "before.exr") +
                                 "material set sigma_a 0.3 0.1 0.3\nlight set /_OpalView/KeyLight exposure 1\n" +
                                 saveExr(dir, "edited.exr") + "undo\nundo\n" + saveExr(dir, "undone.exr") +
                                 "redo\nredo\n" + saveExr(dir, "redone.exr") + "quit\n");
    const ViewRun run = runOpalView(dir, "--size 320x240 --script " + shellWord(dir / "undo.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string before = slurpFile(dir / "before.exr"), edited = slurpFile(dir / "edited.exr");
    ASSERT_FALSE(before.empty());
    EXPECT_NE(before, edited);
    EXPECT_TRUE(slurpFile(dir / "undone.exr") == before) << "undo: the EXR differs from the one before the edits";
    EXPECT_TRUE(slurpFile(dir / "redone.exr") == edited) << "redo: the EXR differs from the edited one";
}

TEST(EditHistory, UndoWithNothingToUndoFailsWithItsLine) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path script = dir.write("undo.script", "load " + scriptWord(asset) + "\nredo\n");
    const ViewRun run = runOpalView(dir, "--size 160x120 --script " + shellWord(script));
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find(script.string() + ":2: nothing to redo"), std::string::npos) << run.err;
}

TEST(EditHistory, DisablingTheOnlyLightLeavesTheAssetUnlitAndEnablingItRestoresThePicture) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("light.script", "load " + scriptWord(asset) + "\n" + saveExr(dir, "on.exr") +
                                  "light disable /_OpalView/KeyLight\n" + saveExr(dir, "off.exr") +
                                  "light enable /_OpalView/KeyLight\n" + saveExr(dir, "again.exr") + "quit\n");
    const ViewRun run = runOpalView(dir, "--size 320x240 --script " + shellWord(dir / "light.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage on = readImage(dir / "on.exr"), off = readImage(dir / "off.exr");
    EXPECT_GT(channelMean(on, "subsurface.G"), 1e-4);
    for (const char* channel : {"subsurface.R", "subsurface.G", "subsurface.B"}) {
        const int c = off.channel(channel);
        float brightest = 0.0f;
        for (int y = 0; y < off.height; ++y)
            for (int x = 0; x < off.width; ++x) brightest = std::max(brightest, std::abs(off.at(x, y, c)));
        EXPECT_EQ(brightest, 0.0f) << channel << " with the only light disabled";
    }
    EXPECT_TRUE(slurpFile(dir / "again.exr") == slurpFile(dir / "on.exr")) << "enabled again: the EXR differs";
}

TEST(EditHistory, LightsAreAddedRenamedAndRemoved) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("lights.script", "load " + scriptWord(asset) + "\n" + saveExr(dir, "key.exr") + "light add distant /Sun\n" +
                                   saveExr(dir, "sun.exr") + "light rename /Sun Sky\nlight add point\nsave usda " +
                                   scriptWord(dir / "saved.usda") + "\nlight remove /Sky\nlight remove /_OpalView/Lights/Point1\n" +
                                   saveExr(dir, "removed.exr") + "light rename /_OpalView/KeyLight 9lives\n");
    const ViewRun run = runOpalView(dir, "--size 320x240 --script " + shellWord(dir / "lights.script"));
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.out.find("opal-view: renamed light to /Sky"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("opal-view: added light /_OpalView/Lights/Point1"), std::string::npos) << run.out;
    EXPECT_NE(run.err.find("lights.script:11: '9lives' is not a prim name"), std::string::npos) << run.err;
    const ReadImage key = readImage(dir / "key.exr"), sun = readImage(dir / "sun.exr");
    EXPECT_GT(channelMean(sun, "irradiance.G"), channelMean(key, "irradiance.G") * 1.2) << "the sun adds light";
    // Removing a light subtracts its part of the relit sums: back within rounding.
    const double removed = maxDifference(key, readImage(dir / "removed.exr"));
    std::cout << "two lights added and removed: max difference from the key light alone " << removed << '\n';
    EXPECT_LT(removed, 1e-6);
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_NE(layer.find("def DistantLight \"Sky\""), std::string::npos) << layer;
    EXPECT_NE(layer.find("def SphereLight \"Point1\""), std::string::npos) << layer;
    EXPECT_EQ(layer.find("\"Sun\""), std::string::npos) << layer;
}

}  // namespace
}  // namespace opal::test
