// Saving a scene whose asset is applied through an over-layer (opal-bake --apply-to,
// sublayered over the user's layer): the saved layer would reference the over-layer, which
// does not load on its own, so the save is refused naming the prim, and nothing is written.
#include "bake/bake_pipeline.h"
#include "delegate/render_delegate.h"
#include "examples/opal-view/core/viewer_model.h"
#include "schema/error.h"
#include "tests/bake/over_layer_scenes.h"
#include "tests/scene/scene_test_files.h"

#include <gtest/gtest.h>

namespace opal::test {
namespace {

TEST(OverLayerSave, ASceneComposedFromAnOverLayerIsRefusedNamingThePrim) {
    const SceneDir dir;
    dir.write("assets/user.usda", overLayerUserLayer());
    const BakeOptions applied = overLayerBakeOptions((dir / "assets/user.usda").string(), "/World/Statue");
    writeBakedAsset(dir / "assets/statue.over", bakeAsset(applied, nullptr, CancelToken(), nullptr), nullptr,
                    applied.applyTo);
    const std::filesystem::path stack = dir.write(
        "stack.usda", "#usda 1.0\n(\n    metersPerUnit = 0.001\n    subLayers = [@./assets/statue.over.usda@, "
                      "@./assets/user.usda@]\n)\n");
    OpalRenderDelegate delegate;
    view::ViewerModel model(delegate, 48, 32);
    model.open(stack);
    ASSERT_EQ(model.scene().meshes.count("/World/Statue"), 1u);
    std::string error = "(no error)";
    try {
        model.saveScene(dir / "saved.usda");
    } catch (const Error& e) {
        error = e.what();
    }
    EXPECT_NE(error.find("cannot save /World/Statue: its asset is applied through an over-layer"), std::string::npos)
        << error;
    EXPECT_FALSE(std::filesystem::exists(dir / "saved.usda"));
}

}  // namespace
}  // namespace opal::test
