// A scene that sublayers an asset's over-layer (opal-bake --apply-to) over the user's own
// layer renders what the plain asset renders when a scene places it with the same
// transforms (examples/scene/layer_stack.h, applied_asset_mesh.h). Both assets are baked
// here from the same 10 mm cube (256 samples, otherwise the shipped defaults) and both
// scenes render through opal-render at its defaults; the truth is the plain asset's image.
// Refusals of a stack name file:line:column.
#include "bake/bake_pipeline.h"
#include "examples/scene/scene_reader.h"
#include "schema/error.h"
#include "tests/bake/over_layer_scenes.h"
#include "tests/scene/opal_render_process.h"
#include "tests/scene/scene_test_files.h"
#include "tests/support/scene_usda.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace opal::scene::over_layer_test {
namespace {

// A key light, a camera 46 mm in front of the cube (which the user's layer puts at
// (4, -2, -6)), and a small image.
std::string lightsAndCamera() {
    using namespace test::usda;
    return "\n" + pointLight("Key", "6000", translate({25, 20, 20})) + camera("Camera", translate({4, -2, 40})) +
           renderSettings(60, 40);
}

std::string stackScene(const std::string& subLayers) {
    return "#usda 1.0\n(\n    metersPerUnit = 0.001\n    subLayers = [" + subLayers + "]\n)\n" + lightsAndCamera();
}

// The plain asset placed as the user's layer places its cube: the Xform's and the Mesh's
// own transforms.
std::string plainScene() {
    return R"(#usda 1.0
(
    metersPerUnit = 0.001
)

def Xform "World"
{
    double3 xformOp:translate = (4, -2, -6)
    float3 xformOp:rotateXYZ = (20, 35, 0)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]

    def Mesh "Statue" (
        references = @./assets/plain.usda@
    )
    {
        double3 xformOp:scale = (1.5, 1.5, 1.5)
        uniform token[] xformOpOrder = ["xformOp:scale"]
    }
}
)" + lightsAndCamera();
}

// The user's layer, the over-layer baked for its /World/Statue and the plain asset of the
// same cube, all in assets/ (so that the stack's asset paths must be re-anchored).
void bakeBoth(const test::SceneDir& dir) {
    dir.write("assets/user.usda", test::overLayerUserLayer());
    dir.write("assets/Statue.usda", test::overLayerCubeAlone());
    const BakeOptions applied = test::overLayerBakeOptions((dir / "assets/user.usda").string(), "/World/Statue");
    writeBakedAsset(dir / "assets/statue.over", bakeAsset(applied, nullptr, CancelToken(), nullptr), nullptr,
                    applied.applyTo);
    const BakeOptions plain = test::overLayerBakeOptions((dir / "assets/Statue.usda").string());
    writeBakedAsset(dir / "assets/plain", bakeAsset(plain, nullptr, CancelToken(), nullptr), nullptr);
}

std::string errorOf(const std::filesystem::path& scene) {
    AssetCache assets;
    try {
        readScene(scene, assets);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// "file:line:column" of the first line of `text` holding `needle`, at its first non-blank.
std::string where(const std::filesystem::path& file, const std::string& text, const std::string& needle) {
    std::size_t start = 0;
    for (int line = 1;; ++line) {
        const std::size_t end = text.find('\n', start);
        const std::string row = text.substr(start, end - start);
        if (row.find(needle) != std::string::npos)
            return file.string() + ":" + std::to_string(line) + ":" + std::to_string(row.find_first_not_of(' ') + 1);
        if (end == std::string::npos) return "(not found)";
        start = end + 1;
    }
}

TEST(OverLayerScene, TheSublayeredStackRendersAsThePlainAssetPlacedTheSameWay) {
    const test::SceneDir dir;
    bakeBoth(dir);
    dir.write("stack.usda", stackScene("@./assets/statue.over.usda@, @./assets/user.usda@"));
    dir.write("plain.usda", plainScene());
    const ProcessResult stack = runOpalRender(dir, "'" + (dir / "stack.usda").string() + "' -o '" +
                                                       (dir / "stack.exr").string() + "'");
    ASSERT_EQ(stack.exitCode, 0) << stack.err;
    const ProcessResult plain = runOpalRender(dir, "'" + (dir / "plain.usda").string() + "' -o '" +
                                                       (dir / "plain.exr").string() + "'");
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const std::vector<float> got = exrPixels(dir / "stack.exr"), expected = exrPixels(dir / "plain.exr");
    ASSERT_FALSE(expected.empty());
    ASSERT_EQ(got.size(), expected.size());
    // Lit: the cube covers part of the picture, and not all of it (channel 0 is red).
    const int channels = exrChannelCount(dir / "plain.exr");
    ASSERT_GT(channels, 3);
    std::vector<double> peak(std::size_t(channels), 0.0);  // per channel, of the finite values
    for (std::size_t i = 0; i < expected.size(); ++i)
        if (std::isfinite(expected[i])) peak[i % channels] = std::max(peak[i % channels], double(std::abs(expected[i])));
    ASSERT_GT(peak[0], 0.0);
    std::size_t dark = 0;
    for (std::size_t i = 0; i < expected.size(); i += std::size_t(channels)) dark += expected[i] == 0.0f;
    ASSERT_GT(dark, 0u);
    // Tolerance: 1e-6 of the channel's peak for every channel of every pixel (AOVs
    // included; non-finite values, such as the background's depth, must match exactly). The
    // two scenes hold the same asset data (the same cube, options and seed) at the same
    // matrices; measured identical.
    std::size_t off = 0;
    double largest = 0.0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        const double a = got[i], b = expected[i];
        if (!std::isfinite(b)) {
            off += !(a == b || (std::isnan(a) && std::isnan(b)));
            continue;
        }
        largest = std::max(largest, std::abs(a - b) / std::max(peak[i % channels], 1e-30));
        off += !(std::abs(a - b) <= 1e-6 * peak[i % channels]);
    }
    EXPECT_EQ(off, 0u) << "values off: " << off << " of " << got.size() << "; largest relative difference " << largest;
}

TEST(OverLayerScene, StacksOpalCannotRenderAreRefusedWithFileLineColumn) {
    const test::SceneDir dir;
    bakeBoth(dir);
    const std::string user = test::overLayerUserLayer();
    const std::filesystem::path userFile = dir / "assets/user.usda";

    // The user's layer listed first is the stronger: its Catmull-Clark cage would win over
    // the render mesh.
    dir.write("weak.usda", stackScene("@./assets/user.usda@, @./assets/statue.over.usda@"));
    const std::string weak = errorOf(dir / "weak.usda");
    EXPECT_EQ(weak.rfind(where(userFile, user, "uniform token subdivisionScheme") + ": Mesh </World/Statue>", 0), 0u)
        << weak;
    EXPECT_NE(weak.find("strongest"), std::string::npos) << weak;

    // The over-layer alone: its overs define nothing.
    dir.write("alone.usda", stackScene("@./assets/statue.over.usda@"));
    const std::string overText = slurp(dir / "assets/statue.over.usda");
    const std::string alone = errorOf(dir / "alone.usda");
    EXPECT_EQ(alone.rfind(where(dir / "assets/statue.over.usda", overText, "over \"World\"") + ": over </World>", 0), 0u)
        << alone;

    const std::string missing = (dir.write("missing.usda", stackScene("@./assets/absent.usda@")), errorOf(dir / "missing.usda"));
    EXPECT_EQ(missing.rfind((dir / "missing.usda").string() + ": subLayers: @./assets/absent.usda@ does not exist", 0), 0u)
        << missing;
    dir.write("loop.usda", stackScene("@./loop2.usda@"));
    dir.write("loop2.usda", stackScene("@./loop.usda@"));
    EXPECT_NE(errorOf(dir / "loop.usda").find("makes a cycle"), std::string::npos) << errorOf(dir / "loop.usda");

    // The control: the stack in strength order reads, with the cube as a translucent mesh.
    dir.write("stack.usda", stackScene("@./assets/statue.over.usda@, @./assets/user.usda@"));
    AssetCache assets;
    const Scene scene = readScene(dir / "stack.usda", assets);
    ASSERT_EQ(scene.meshes.count("/World/Statue"), 1u);
    EXPECT_EQ(scene.meshes.at("/World/Statue").desc.asset->name, "Statue");
}

}  // namespace
}  // namespace opal::scene::over_layer_test
