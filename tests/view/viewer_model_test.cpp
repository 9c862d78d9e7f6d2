// The viewer's document without a window: the title's unsaved mark follows the material and
// light edits, undo and redo (a held slider is one step), and saving; the undo stack itself.
#include "delegate/render_delegate.h"
#include "examples/opal-view/core/undo_stack.h"
#include "examples/opal-view/core/viewer_model.h"
#include "schema/error.h"
#include "tests/scene/scene_test_files.h"

#include <gtest/gtest.h>

namespace opal::view {
namespace {

bool marked(const ViewerModel& model) { return model.title().find(" *") != std::string::npos; }

TEST(UndoStack, UndoesAndRedoesWholeStatesAndAnEditForgetsTheRedos) {
    UndoStack<int> stack(2);
    EXPECT_FALSE(stack.undo(0));
    stack.push(1);
    stack.push(2);
    stack.push(3);  // the oldest, 1, goes
    EXPECT_EQ(stack.undo(4), 3);
    EXPECT_EQ(stack.undo(3), 2);
    EXPECT_FALSE(stack.undo(2));
    EXPECT_EQ(stack.redo(2), 3);
    stack.push(3);
    EXPECT_FALSE(stack.canRedo());
}

class ModelTest : public ::testing::Test {
protected:
    test::SceneDir dir;
    OpalRenderDelegate delegate;
    ViewerModel model{delegate, 48, 32};

    void SetUp() override { model.open(dir.writeSphereAsset("sphere")); }
    Rgb absorption() const { return model.selectedMaterial().subsurface.sigmaA; }
};

TEST_F(ModelTest, TheTitleNamesTheFileAndMarksUnsavedEditsUntilSaved) {
    EXPECT_NE(model.title().find("sphere.usda"), std::string::npos) << model.title();
    EXPECT_FALSE(marked(model));
    const double sigmaA[] = {0.3, 0.1, 0.3};
    model.setMaterialParameter("sigma_a", sigmaA);
    EXPECT_TRUE(marked(model)) << model.title();
    model.undo();
    EXPECT_FALSE(marked(model)) << "back where it was opened";
    model.redo();
    EXPECT_TRUE(marked(model));
    model.saveScene(dir / "saved.usda");
    EXPECT_FALSE(marked(model)) << model.title();
    EXPECT_NE(model.title().find("saved.usda"), std::string::npos) << model.title();
    model.undo();
    EXPECT_TRUE(marked(model)) << "undone past the save";
    model.camera.yaw += 30.0;
    model.redo();
    EXPECT_FALSE(marked(model)) << "the camera is not an edit";
}

TEST_F(ModelTest, EditsMadeWhileMergingAreOneUndoStep) {
    const Rgb start = absorption();
    model.setMergingEdits(true);
    for (const double g : {0.12, 0.14, 0.16}) {
        const double sigmaA[] = {0.05, g, 0.2};
        model.setMaterialParameter("sigma_a", sigmaA);
    }
    model.setMergingEdits(false);
    EXPECT_EQ(absorption()[1], double(0.16f)) << "edits hold what a layer's float holds";
    const double sigmaA[] = {0.05, 0.2, 0.2};
    model.setMaterialParameter("sigma_a", sigmaA);
    ASSERT_TRUE(model.undo());
    EXPECT_EQ(absorption()[1], double(0.16f));
    ASSERT_TRUE(model.undo());
    EXPECT_EQ(absorption(), start);
    EXPECT_FALSE(model.undo());
}

TEST_F(ModelTest, LightEditsUndoIncludingAddRemoveRenameAndEnable) {
    const hd::SdfPath added = model.addLight(NewLightKind::Dome);
    EXPECT_EQ(added, "/_OpalView/Lights/Dome1");
    const hd::SdfPath renamed = model.renameLight(added, "Sky");
    model.setLightEnabled(KeyLightPath, false);
    model.removeLight(renamed);
    EXPECT_EQ(model.scene().lights.size(), 1u);
    EXPECT_FALSE(model.lightEnabled(KeyLightPath));
    model.undo();  // the removal
    EXPECT_TRUE(model.scene().lights.count("/_OpalView/Lights/Sky"));
    model.undo();  // disabling
    EXPECT_TRUE(model.lightEnabled(KeyLightPath));
    model.undo();  // the rename
    EXPECT_TRUE(model.scene().lights.count(added));
    model.undo();  // the addition
    EXPECT_EQ(model.scene().lights.size(), 1u);
    EXPECT_FALSE(marked(model));
    EXPECT_THROW(model.renameLight(KeyLightPath, "a/b"), Error);
    EXPECT_THROW(model.addLight(NewLightKind::Point, KeyLightPath), Error);
}

TEST_F(ModelTest, APresetOutsideTheAssetsRangeIsRefusedNamingIt) {
    try {
        model.applyPreset("ketchup");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("preset 'ketchup': "), std::string::npos) << e.what();
    }
    EXPECT_THROW(model.applyPreset("jelly"), Error);
    EXPECT_FALSE(marked(model));
}

}  // namespace
}  // namespace opal::view

namespace opal::view {
namespace {

std::string settingError(ViewerModel& model, const char* key, const char* value) {
    try {
        model.setRenderSettingText(key, value);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// Checked against the delegate's descriptors before the worker sets them (where a refusal
// could only be reported later); the value waiting is the one the panel shows.
TEST_F(ModelTest, RenderSettingsAreCheckedAgainstTheDescriptorsAndWaitForTheWorker) {
    EXPECT_EQ(settingError(model, "opal:samplesPerPixel", "5000"), "setting opal:samplesPerPixel: 5000 is outside [1, 1024]");
    EXPECT_EQ(settingError(model, "opal:pixelFilter", "gauss"),
              "setting opal:pixelFilter: 'gauss' is not one of box, blackmanHarris");
    EXPECT_EQ(settingError(model, "opal:tileSize", "big"), "setting opal:tileSize: 'big' is not an integer");
    EXPECT_EQ(settingError(model, "opal:bogus", "1").rfind("the renderer has no setting 'opal:bogus' (settings: ", 0), 0u);
    model.setRenderSettingText("opal:samplesPerPixel", "4");
    EXPECT_EQ(model.renderSetting("opal:samplesPerPixel"), hd::Value(4));
    EXPECT_FALSE(model.settled()) << "a setting waiting for the worker";
}

}  // namespace
}  // namespace opal::view

namespace opal::view {
namespace {

// A preset inside the asset's range: its coefficients as a layer's floats hold them, the
// specular layer kept, one undo step.
TEST(ModelPresets, APresetSetsTheMeasuredCoefficientsAndUndoesInOneStep) {
    const test::SceneDir dir;
    auto asset = std::make_shared<TranslucentAsset>(*test::sphereAsset(2, 5.0f, 0));
    asset->range = EditableRange::coveringPresets();
    asset->bake.identifier = 0x5e1f0b5e55ed0002ull;
    writeSidecar(dir / "wide.opal", *asset);
    writeAssetLayer(dir / "wide.usda", *asset, "./wide.opal");
    OpalRenderDelegate delegate;
    ViewerModel model(delegate, 48, 32);
    model.open(dir / "wide.usda");
    const hd::MaterialDesc before = model.selectedMaterial();
    const double rough[] = {0.5};
    model.setMaterialParameter("roughness", rough);
    model.applyPreset("skimmilk");
    const Material milk = *findPreset("skimmilk");
    const hd::MaterialDesc& now = model.selectedMaterial();
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(now.subsurface.sigmaSPrime[c], double(float(milk.sigmaSPrime[c])));
        EXPECT_EQ(now.subsurface.sigmaA[c], double(float(milk.sigmaA[c])));
    }
    EXPECT_EQ(now.subsurface.eta, double(float(milk.eta)));
    EXPECT_EQ(now.specularRoughness, 0.5);
    ASSERT_TRUE(model.undo());
    EXPECT_EQ(model.selectedMaterial().specularRoughness, 0.5);
    EXPECT_EQ(model.selectedMaterial().subsurface.sigmaA[1], before.subsurface.sigmaA[1]);
}

}  // namespace
}  // namespace opal::view
