// composeLayerStack (examples/scene/layer_stack.h) on small stacks written here: what each
// layer contributes, worked out by hand from USD's composition rules for the subset.
#include "examples/scene/layer_stack.h"
#include "tests/scene/scene_test_files.h"

#include <gtest/gtest.h>

namespace opal::scene::layer_stack_test {
namespace {

float floatOf(const usda::Prim& prim, const std::string& name) {
    const float* value = prim.findValue<usda::types::Float>(name);
    return value ? *value : -1.0f;
}

TEST(LayerStack, StrongerOpinionsWinAndTheWeakerLayerProvidesTheRest) {
    const test::SceneDir dir;
    dir.write("scene.usda", R"(#usda 1.0
(
    metersPerUnit = 0.001
    subLayers = [@./sub/strong.usda@, @./weak.usda@]
)

def Scope "Root"
{
}
)");
    dir.write("sub/strong.usda", R"(#usda 1.0
(
    metersPerUnit = 1
)

over "A" (
    prepend apiSchemas = ["StrongAPI", "SharedAPI"]
)
{
    float declared
    float overridden = 2
    uniform asset file = @./texture.exr@

    over "B" (
        references = @./thing.usda@
    )
    {
    }
}
)");
    dir.write("weak.usda", R"(#usda 1.0

def Xform "A" (
    kind = "group"
    prepend apiSchemas = ["SharedAPI", "WeakAPI"]
)
{
    float declared = 1
    float overridden = 5
    float weakOnly = 7

    def "C"
    {
    }
}

def "D"
{
}
)");
    const usda::Layer layer = composeLayerStack(dir / "scene.usda");
    EXPECT_TRUE(layer.subLayers.empty());
    EXPECT_EQ(*layer.metersPerUnit(), 0.001);  // the scene layer's own metadata only
    std::vector<std::string> roots;
    for (const usda::Prim& p : layer.rootPrims) roots.push_back(p.name);
    EXPECT_EQ(roots, (std::vector<std::string>{"Root", "A", "D"}));

    const usda::Prim& a = layer.prim("/A");
    EXPECT_EQ(a.specifier, usda::Specifier::Def);  // the weaker def defines the over
    EXPECT_EQ(a.typeName, "Xform");
    EXPECT_EQ(a.kind(), "group");
    EXPECT_EQ(a.apiSchemas.composed(), (std::vector<std::string>{"StrongAPI", "SharedAPI", "WeakAPI"}));
    EXPECT_EQ(floatOf(a, "declared"), 1.0f);  // declared without a value: the weaker value
    EXPECT_EQ(floatOf(a, "overridden"), 2.0f);
    EXPECT_EQ(floatOf(a, "weakOnly"), 7.0f);
    // Asset paths of sub/strong.usda resolve from sub/, as in their own layer.
    EXPECT_EQ(*a.findValue<usda::types::Asset>("file"), "./sub/texture.exr");
    const usda::Prim& b = layer.prim("/A/B");
    EXPECT_EQ(b.specifier, usda::Specifier::Over);  // no layer defines it
    ASSERT_EQ(b.references.composed().size(), 1u);
    EXPECT_EQ(b.references.composed().front().assetPath, "./sub/thing.usda");
    EXPECT_EQ(layer.prim("/A/C").specifier, usda::Specifier::Def);
}

TEST(LayerStack, AnExplicitListReplacesTheWeakerOne) {
    const test::SceneDir dir;
    dir.write("scene.usda", "#usda 1.0\n(\n    subLayers = [@./weak.usda@]\n)\n\nover \"A\" (\n"
                            "    apiSchemas = [\"OnlyAPI\"]\n)\n{\n}\n");
    dir.write("weak.usda", "#usda 1.0\n\ndef \"A\" (\n    prepend apiSchemas = [\"WeakAPI\"]\n)\n{\n}\n");
    EXPECT_EQ(composeLayerStack(dir / "scene.usda").prim("/A").apiSchemas.composed(),
              std::vector<std::string>{"OnlyAPI"});
}

}  // namespace
}  // namespace opal::scene::layer_stack_test
