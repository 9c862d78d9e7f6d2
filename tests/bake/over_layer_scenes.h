// What the over-layer tests share (tests/bake for the bake and the layer it writes,
// tests/scene for rendering the stack): a user's layer holding a Catmull-Clark cube under
// a transformed Xform, the same cube alone at the origin for the plain bake, and the bake
// options both use (256 samples, otherwise the shipped defaults).
#pragma once

#include "bake/bake_pipeline.h"

#include <string>

namespace opal::test {

// The cube's control points and faces (10 mm across, outward counter-clockwise quads).
inline std::string overLayerCubeBody() {
    return R"(        int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
        int[] faceVertexIndices = [0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 0, 4, 7, 3]
        point3f[] points = [(-5, -5, -5), (5, -5, -5), (5, 5, -5), (-5, 5, -5), (-5, -5, 5), (5, -5, 5), (5, 5, 5), (-5, 5, 5)]
        uniform token subdivisionScheme = "catmullClark"
)";
}

// The user's asset layer: /World/Statue, with transforms on the Mesh and its parent (which
// the over-layer must keep, not bake in), normals and a UV set for the control mesh, and
// around it a class, an inactive prim and a Scope, for the refusals.
inline std::string overLayerUserLayer() {
    return R"(#usda 1.0
(
    metersPerUnit = 0.001
    upAxis = "Y"
)

def Xform "World" (
    kind = "assembly"
)
{
    double3 xformOp:translate = (4, -2, -6)
    float3 xformOp:rotateXYZ = (20, 35, 0)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]

    def Mesh "Statue" (
        kind = "component"
    )
    {
)" + overLayerCubeBody() +
           R"(        normal3f[] normals = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)] (
            interpolation = "vertex"
        )
        texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0), (1, 0), (1, 1), (0, 1)] (
            interpolation = "vertex"
        )
        double3 xformOp:scale = (1.5, 1.5, 1.5)
        uniform token[] xformOpOrder = ["xformOp:scale"]
    }

    class "Template"
    {
        def Mesh "Shape"
        {
)" + overLayerCubeBody() +
           R"(        }
    }

    def Mesh "Retired" (
        active = false
    )
    {
)" + overLayerCubeBody() +
           R"(    }

    def Scope "Props"
    {
    }
}
)";
}

// The same cube alone, untransformed, as the plain bake's input (a file named Statue.usda
// gives the asset the prim's name).
inline std::string overLayerCubeAlone() {
    return "#usda 1.0\n(\n    metersPerUnit = 0.001\n)\n\ndef Mesh \"Statue\"\n{\n" + overLayerCubeBody() + "}\n";
}

inline BakeOptions overLayerBakeOptions(const std::string& input, const std::string& applyTo = {}) {
    BakeOptions options;
    options.input = input;
    options.applyTo = applyTo;
    options.samples = 256;
    return options;
}

}  // namespace opal::test
