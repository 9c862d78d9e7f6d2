// The prim paths the viewer makes (examples/opal-view/core/prim_path.h): names, siblings,
// and what a new prim may not be called.
#include "examples/opal-view/core/prim_path.h"

#include "schema/error.h"

#include <gtest/gtest.h>

namespace opal::view {
namespace {

TEST(PrimPath, NameIsTheLastElement) {
    EXPECT_EQ(primName("/World/Lights/Key"), "Key");
    EXPECT_EQ(primName("/Key"), "Key");
}

TEST(PrimPath, SiblingReplacesOnlyTheLastElement) {
    EXPECT_EQ(siblingPath("/World/Lights/Key", "Fill"), "/World/Lights/Fill");
    EXPECT_EQ(siblingPath("/Key", "Fill"), "/Fill");
}

TEST(PrimPath, IdentifiersAreUsdIdentifiers) {
    EXPECT_TRUE(isIdentifier("Key_2"));
    EXPECT_TRUE(isIdentifier("_fill"));
    EXPECT_FALSE(isIdentifier("2Key"));
    EXPECT_FALSE(isIdentifier("Key Light"));
    EXPECT_FALSE(isIdentifier(""));
}

TEST(PrimPath, ANewPrimPathMustBeFreeAndWellFormed) {
    scene::Scene scene;
    scene.lights["/World/Key"] = scene::SceneLight{};
    EXPECT_NO_THROW(requireNewPrimPath(scene, "/World/Fill"));
    EXPECT_THROW(requireNewPrimPath(scene, "/World/Key"), Error);
    EXPECT_THROW(requireNewPrimPath(scene, "World/Fill"), Error);
    EXPECT_THROW(requireNewPrimPath(scene, "/World/2Fill"), Error);
}

}  // namespace
}  // namespace opal::view
