// The material a mesh renders with, as both delegates resolve its binding
// (delegate/hd/mesh_material.h; DELEGATE.md): no binding is the asset's default material
// with the specular layer on at roughness 0.35, a binding is the prim's description, and a
// binding to no material prim is an error naming the path.
#include "delegate/hd/mesh_material.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <string>

namespace opal {
namespace {

TranslucentAsset assetWithDefault() {
    TranslucentAsset asset;
    asset.defaultMaterial = Material{{1.2, 0.9, 0.7}, {0.05, 0.1, 0.2}, 1.4};
    return asset;
}

TEST(MeshMaterial, WithoutABindingTheAssetsDefaultUnderTheDefaultSpecularLayer) {
    const hd::MaterialDesc bound{Material{{2.0, 2.0, 2.0}, {0.5, 0.5, 0.5}, 1.5}, false, 0.9};
    const hd::MaterialDesc m = hd::meshMaterial("", assetWithDefault(), &bound);  // no binding: not used
    EXPECT_EQ(m.subsurface.sigmaSPrime[1], 0.9);
    EXPECT_EQ(m.subsurface.sigmaA[2], 0.2);
    EXPECT_EQ(m.subsurface.eta, 1.4);
    EXPECT_TRUE(m.specular);
    EXPECT_EQ(m.specularRoughness, double(0.35f));  // the default, as a layer's float holds it
}

TEST(MeshMaterial, ABindingIsThePrimsDescription) {
    const hd::MaterialDesc bound{Material{{2.0, 2.0, 2.0}, {0.5, 0.5, 0.5}, 1.5}, false, 0.9};
    const hd::MaterialDesc m = hd::meshMaterial("/Looks/Jade", assetWithDefault(), &bound);
    EXPECT_EQ(m.subsurface.sigmaSPrime[0], 2.0);
    EXPECT_EQ(m.subsurface.eta, 1.5);
    EXPECT_FALSE(m.specular);
    EXPECT_EQ(m.specularRoughness, 0.9);
}

TEST(MeshMaterial, ABindingToNoMaterialPrimIsAnErrorNamingThePath) {
    try {
        hd::meshMaterial("/Looks/Gone", assetWithDefault(), nullptr);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "its material '/Looks/Gone' is not a material prim of the render index");
    }
}

}  // namespace
}  // namespace opal
