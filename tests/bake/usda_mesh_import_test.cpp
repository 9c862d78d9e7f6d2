// USDA meshes through importMesh (bake/usda_mesh_import.h), against independent truths:
// the same cube through the Assimp OBJ path, transforms worked out by hand, an asset
// opal-bake wrote read back point for point, flat (bilinear) refinement staying on the
// octahedron |x|+|y|+|z| = 1, and the exact file:line:column of each refusal. The CLI
// cases run opal-bake as a child process, as tests/bake/opal_bake_cli_test.cpp does.
#include "bake/bake_pipeline.h"
#include "bake/mesh_import.h"
#include "bake/mesh_validation.h"
#include "schema/error.h"
#include "tests/bake/bake_test_support.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for opal-test-bake"
#endif

namespace opal {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using test::ScratchDir;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---- writing meshes as USDA and OBJ -------------------------------------------------

std::string pointList(const std::vector<Imath::V3f>& points) {
    std::ostringstream s;
    s.precision(9);
    for (std::size_t v = 0; v < points.size(); ++v)
        s << (v ? ", " : "") << "(" << points[v].x << ", " << points[v].y << ", " << points[v].z << ")";
    return s.str();
}

std::string intList(const std::vector<std::int32_t>& values) {
    std::string s;
    for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + std::to_string(values[i]);
    return s;
}

// A Mesh prim holding `mesh`; `extra` lines go into its body (8-space indented).
std::string meshPrim(const std::string& name, const ControlMesh& mesh, const std::string& extra = "",
                     const std::string& indent = "") {
    return indent + "def Mesh \"" + name + "\"\n" + indent + "{\n" + indent + "    int[] faceVertexCounts = [" +
           intList(mesh.faceVertexCounts) + "]\n" + indent + "    int[] faceVertexIndices = [" +
           intList(mesh.faceVertexIndices) + "]\n" + indent + "    point3f[] points = [" + pointList(mesh.positions) +
           "]\n" + extra + indent + "}\n";
}

std::string layer(const std::string& prims, const std::string& metadata = "") {
    return "#usda 1.0\n" + (metadata.empty() ? std::string() : "(\n    " + metadata + "\n)\n") + "\n" + prims;
}

// Each face as its corner positions, to compare meshes whose vertex numbering differs.
std::vector<std::vector<Imath::V3f>> facePositions(const ControlMesh& m) {
    std::vector<std::vector<Imath::V3f>> faces;
    std::size_t start = 0;
    for (std::int32_t n : m.faceVertexCounts) {
        std::vector<Imath::V3f> face;
        for (std::int32_t c = 0; c < n; ++c) face.push_back(m.positions[m.faceVertexIndices[start + std::size_t(c)]]);
        faces.push_back(face);
        start += std::size_t(n);
    }
    return faces;
}

// [a, b, c, d] -> [a, d, c, b]: the same face wound the other way.
std::vector<std::int32_t> reversedFaces(const ControlMesh& m) {
    std::vector<std::int32_t> out;
    std::size_t start = 0;
    for (std::int32_t n : m.faceVertexCounts) {
        for (std::int32_t c = 0; c < n; ++c) out.push_back(m.faceVertexIndices[start + std::size_t((n - c) % n)]);
        start += std::size_t(n);
    }
    return out;
}

std::string errorOf(const fs::path& path) {
    try {
        importMesh(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// "path:line:column" of the first occurrence of `needle`.
std::string locationOf(const fs::path& path, const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!contains(line, needle)) continue;
        return path.string() + ":" + std::to_string(number) + ":" + std::to_string(line.find(needle) + 1);
    }
    return "(not found)";
}

// ---- the mesh as authored -----------------------------------------------------------

TEST(UsdaMeshImport, QuadCubeMatchesTheSameCubeThroughTheObjReader) {
    const ScratchDir dir;
    const ControlMesh cube = test::cube();
    test::writeText(dir / "cube.usda", layer(meshPrim("Cube", cube)));
    test::writeText(dir / "cube.obj", test::objText(cube));
    ImportedMesh usda = importMesh(dir / "cube.usda");
    ImportedMesh obj = importMesh(dir / "cube.obj");
    // As authored: the same points, counts and indices, quads kept.
    EXPECT_EQ(usda.mesh.positions, cube.positions);
    EXPECT_EQ(usda.mesh.faceVertexCounts, cube.faceVertexCounts);
    EXPECT_EQ(usda.mesh.faceVertexIndices, cube.faceVertexIndices);
    EXPECT_FALSE(usda.mesh.hasUvs());
    EXPECT_EQ(usda.mesh.source, (dir / "cube.usda").string());
    EXPECT_TRUE(usda.warnings.empty()) << usda.warnings.front();
    EXPECT_FALSE(usda.authoredScheme);
    EXPECT_FALSE(usda.metersPerUnit);
    // Through validation and repair, the same faces as the Assimp path gives.
    EXPECT_TRUE(validateAndRepair(usda.mesh).warnings.empty());
    validateAndRepair(obj.mesh);
    EXPECT_EQ(usda.mesh.faceVertexCounts, obj.mesh.faceVertexCounts);
    EXPECT_EQ(facePositions(usda.mesh), facePositions(obj.mesh));
}

TEST(UsdaMeshImport, LeftHandedOrientationReversesEveryFace) {
    const ScratchDir dir;
    ControlMesh clockwise = test::cube();
    clockwise.faceVertexIndices = reversedFaces(clockwise);
    test::writeText(dir / "left.usda",
                    layer(meshPrim("Cube", clockwise, "    uniform token orientation = \"leftHanded\"\n")));
    ImportedMesh left = importMesh(dir / "left.usda");
    EXPECT_EQ(left.mesh.faceVertexIndices, test::cube().faceVertexIndices);
    EXPECT_TRUE(validateAndRepair(left.mesh).warnings.empty());
    // The control: the same faces read right-handed are inside out, and the repair says so.
    test::writeText(dir / "right.usda", layer(meshPrim("Cube", clockwise)));
    ImportedMesh right = importMesh(dir / "right.usda");
    EXPECT_EQ(right.mesh.faceVertexIndices, clockwise.faceVertexIndices);
    const std::vector<std::string> warnings = validateAndRepair(right.mesh).warnings;
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(contains(warnings[0], "inside out")) << warnings[0];
}

TEST(UsdaMeshImport, HoleFacesAreLeftOut) {
    const ScratchDir dir;
    const ControlMesh cube = test::cube();
    test::writeText(dir / "holes.usda", layer(meshPrim("Cube", cube, "    int[] holeIndices = [1, 4]\n")));
    const ImportedMesh imported = importMesh(dir / "holes.usda");
    std::vector<std::vector<Imath::V3f>> expected = facePositions(cube);
    expected.erase(expected.begin() + 4);
    expected.erase(expected.begin() + 1);
    EXPECT_EQ(facePositions(imported.mesh), expected);
}

// ---- transforms ---------------------------------------------------------------------

// The unit cube's points after a transform, authored as `ops` inside the Mesh prim (and
// `parentOps` on an enclosing Xform).
std::vector<Imath::V3f> transformedCube(const std::string& ops, const std::string& parentOps = "",
                                        std::vector<std::string>* warnings = nullptr,
                                        std::vector<std::int32_t>* indices = nullptr) {
    const ScratchDir dir;
    const std::string text =
        layer("def Xform \"World\"\n{\n" + parentOps + meshPrim("Cube", test::cube(), ops, "    ") + "}\n");
    test::writeText(dir / "cube.usda", text);
    ImportedMesh imported = importMesh(dir / "cube.usda");
    if (warnings) *warnings = imported.warnings;
    if (indices) *indices = imported.mesh.faceVertexIndices;
    return imported.mesh.positions;
}

void expectMapped(const std::vector<Imath::V3f>& got, const std::function<Imath::V3f(Imath::V3f)>& expected) {
    const ControlMesh cube = test::cube();
    ASSERT_EQ(got.size(), cube.positions.size());
    for (std::size_t v = 0; v < got.size(); ++v) {
        const Imath::V3f want = expected(cube.positions[v]);
        EXPECT_NEAR(got[v].x, want.x, 1e-5f) << "point " << v;
        EXPECT_NEAR(got[v].y, want.y, 1e-5f) << "point " << v;
        EXPECT_NEAR(got[v].z, want.z, 1e-5f) << "point " << v;
    }
}

TEST(UsdaMeshImport, AppliesTheXformOpsOfThePrimAndItsAncestorsInUsdOrder) {
    // Listed first acts last: scale, then rotate 90 degrees about z, then the two translates.
    std::vector<std::string> warnings;
    std::vector<std::int32_t> indices;
    const std::vector<Imath::V3f> got = transformedCube(
        "        float3 xformOp:scale = (2, 3, 4)\n"
        "        float xformOp:rotateZ = 90\n"
        "        double3 xformOp:translate:offset = (0, 0, 1)\n"
        "        double3 xformOp:translate:unused = (100, 100, 100)\n"
        "        uniform token[] xformOpOrder = [\"xformOp:translate:offset\", \"xformOp:rotateZ\", \"xformOp:scale\"]\n",
        "    double3 xformOp:translate = (10, 0, 0)\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n",
        &warnings, &indices);
    expectMapped(got, [](Imath::V3f p) { return Imath::V3f(10 - 3 * p.y, 2 * p.x, 4 * p.z + 1); });
    EXPECT_EQ(indices, test::cube().faceVertexIndices);  // no mirroring: winding kept
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "</World/Cube>.xformOp:translate:unused is not in xformOpOrder: ignored, as USD does");
}

TEST(UsdaMeshImport, AppliesMatrixQuaternionEulerInvertAndReset) {
    expectMapped(transformedCube("        matrix4d xformOp:transform = ((0, 1, 0, 0), (-1, 0, 0, 0), (0, 0, 1, 0), "
                                 "(5, 6, 7, 1))\n        uniform token[] xformOpOrder = [\"xformOp:transform\"]\n"),
                 [](Imath::V3f p) { return Imath::V3f(5 - p.y, 6 + p.x, 7 + p.z); });
    // (cos 45, 0, 0, sin 45): 90 degrees about z.
    expectMapped(transformedCube("        quatf xformOp:orient = (0.70710678, 0, 0, 0.70710678)\n"
                                 "        uniform token[] xformOpOrder = [\"xformOp:orient\"]\n"),
                 [](Imath::V3f p) { return Imath::V3f(-p.y, p.x, p.z); });
    // X first: (x, y, z) -> (x, -z, y), then Z: -> (z, x, y).
    expectMapped(transformedCube("        float3 xformOp:rotateXYZ = (90, 0, 90)\n"
                                 "        uniform token[] xformOpOrder = [\"xformOp:rotateXYZ\"]\n"),
                 [](Imath::V3f p) { return Imath::V3f(p.z, p.x, p.y); });
    // A pivot: translate, op, inverse translate. Scaling about (1, 0, 0) by 2 in x.
    expectMapped(transformedCube("        double3 xformOp:translate:pivot = (1, 0, 0)\n"
                                 "        float3 xformOp:scale = (2, 1, 1)\n"
                                 "        uniform token[] xformOpOrder = [\"xformOp:translate:pivot\", "
                                 "\"xformOp:scale\", \"!invert!xformOp:translate:pivot\"]\n"),
                 [](Imath::V3f p) { return Imath::V3f(2 * p.x - 1, p.y, p.z); });
    // !resetXformStack! drops the parent's translate.
    expectMapped(transformedCube("        uniform token[] xformOpOrder = [\"!resetXformStack!\"]\n",
                                 "    double3 xformOp:translate = (10, 0, 0)\n"
                                 "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n"),
                 [](Imath::V3f p) { return p; });
}

TEST(UsdaMeshImport, MirroringTransformKeepsTheFacesOutward) {
    std::vector<std::int32_t> indices;
    const std::vector<Imath::V3f> got = transformedCube(
        "        float3 xformOp:scale = (-1, 1, 1)\n        uniform token[] xformOpOrder = [\"xformOp:scale\"]\n", "",
        nullptr, &indices);
    expectMapped(got, [](Imath::V3f p) { return Imath::V3f(-p.x, p.y, p.z); });
    EXPECT_EQ(indices, reversedFaces(test::cube()));
    ControlMesh mirrored;
    mirrored.positions = got;
    mirrored.faceVertexCounts = test::cube().faceVertexCounts;
    mirrored.faceVertexIndices = indices;
    EXPECT_TRUE(validateAndRepair(mirrored).warnings.empty());  // not inside out
    // Mirrored and left-handed: the two reversals cancel.
    transformedCube("        float3 xformOp:scale = (-1, 1, 1)\n        uniform token[] xformOpOrder = [\"xformOp:scale\"]\n"
                    "        uniform token orientation = \"leftHanded\"\n",
                    "", nullptr, &indices);
    EXPECT_EQ(indices, test::cube().faceVertexIndices);
}

// ---- several prims, and what USD would not render -----------------------------------

TEST(UsdaMeshImport, MergesEveryRenderedMeshPrimAndSaysWhatItSkipped) {
    const ScratchDir dir;
    const ControlMesh cube = test::cube();
    const std::string scheme = "        uniform token subdivisionScheme = \"catmullClark\"\n";
    const std::string at = "        uniform token[] xformOpOrder = [\"xformOp:translate\"]\n";
    const std::string prims =
        "def Xform \"World\"\n{\n" +
        meshPrim("A", cube, scheme + "        double3 xformOp:translate = (-2, 0, 0)\n" + at, "    ") +
        meshPrim("B", cube, scheme + "        double3 xformOp:translate = (2, 0, 0)\n" + at, "    ") +
        meshPrim("Hidden", cube, "        token visibility = \"invisible\"\n", "    ") +
        meshPrim("Guide", cube, "        uniform token purpose = \"guide\"\n", "    ") +
        "    def Sphere \"Ball\"\n    {\n    }\n"
        "    def \"Off\" (\n        active = false\n    )\n    {\n" + meshPrim("C", cube, "", "        ") + "    }\n" +
        "    over \"Over\"\n    {\n" + meshPrim("D", cube, "", "        ") + "    }\n" + "}\n" +
        "class Mesh \"Template\"\n{\n}\n";
    test::writeText(dir / "pair.usda", layer(prims, "metersPerUnit = 0.01"));
    const ImportedMesh imported = importMesh(dir / "pair.usda");
    EXPECT_EQ(imported.mesh.positions.size(), 16u);
    EXPECT_EQ(imported.mesh.faceVertexCounts, std::vector<std::int32_t>(12, 4));
    for (std::size_t v = 0; v < 8; ++v) {
        EXPECT_EQ(imported.mesh.positions[v], cube.positions[v] + Imath::V3f(-2, 0, 0));
        EXPECT_EQ(imported.mesh.positions[8 + v], cube.positions[v] + Imath::V3f(2, 0, 0));
    }
    EXPECT_EQ(imported.authoredScheme, SubdivisionScheme::CatmullClark);
    EXPECT_EQ(imported.metersPerUnit, 0.01);
    EXPECT_EQ(imported.warnings,
              (std::vector<std::string>{
                  "skipped 2 prims holding meshes USD does not render: </World/Hidden> (invisible), "
                  "</World/Guide> (purpose guide)",
                  "ignored 1 geometry prims that are not Mesh prims: </World/Ball> (Sphere)"}));
}

TEST(UsdaMeshImport, DisagreeingSchemesFallBackToTheAutomaticChoice) {
    const ScratchDir dir;
    const ControlMesh octa = test::octahedron();
    test::writeText(dir / "mixed.usda", layer(meshPrim("A", octa, "    uniform token subdivisionScheme = \"none\"\n") +
                                              meshPrim("B", octa)));
    const ImportedMesh imported = importMesh(dir / "mixed.usda");
    EXPECT_FALSE(imported.authoredScheme);
    ASSERT_EQ(imported.warnings.size(), 1u);
    EXPECT_TRUE(contains(imported.warnings[0], "disagree on subdivisionScheme (</A> none, </B> not authored)"))
        << imported.warnings[0];
}

// ---- through the bake ---------------------------------------------------------------

BakeOptions smallBake(const std::string& input) {
    BakeOptions options;
    options.input = input;
    options.level = 1;
    options.samples = 256;
    options.visibility.cubeFaceSize = 8;
    options.visibility.terms = 32;
    return options;
}

TranslucentAsset bake(const BakeOptions& options, BakeReport* report = nullptr) {
    return bakeAsset(options, nullptr, CancelToken(), report);
}

TEST(UsdaMeshImport, ReimportsAnAssetOpalBakeWrote) {
    const ScratchDir dir;
    const TranslucentAsset asset = bake(smallBake("builtin:candle"));
    writeBakedAsset(dir / "candle", asset, nullptr);
    ImportedMesh imported = importMesh(dir / "candle.usda");
    // The render mesh, point for point (the writer's shortest text reads back exactly).
    EXPECT_EQ(imported.mesh.positions, asset.mesh.points);
    EXPECT_EQ(imported.mesh.faceVertexCounts, asset.mesh.faceVertexCounts);
    EXPECT_EQ(imported.mesh.faceVertexIndices, asset.mesh.faceVertexIndices);
    EXPECT_TRUE(imported.warnings.empty()) << imported.warnings.front();
    // The asset says subdivisionScheme "none": it already is the limit surface.
    EXPECT_EQ(imported.authoredScheme, SubdivisionScheme::Bilinear);
    ASSERT_TRUE(imported.metersPerUnit);
    EXPECT_NEAR(*imported.metersPerUnit, 0.001 / asset.unitsPerMm, 1e-15);
    EXPECT_TRUE(validateAndRepair(imported.mesh).warnings.empty());

    // Re-baking it at level 0 keeps the surface exactly: flat refinement moves nothing.
    BakeOptions again = smallBake((dir / "candle.usda").string());
    again.level = 0;
    BakeReport report;
    const TranslucentAsset rebaked = bake(again, &report);
    EXPECT_EQ(rebaked.bake.scheme, "bilinear");
    EXPECT_EQ(rebaked.mesh.points, asset.mesh.points);
    EXPECT_EQ(rebaked.mesh.faceVertexIndices, asset.mesh.faceVertexIndices);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

TEST(UsdaMeshImport, TheBakeHonoursTheAuthoredSchemeUnlessScheme) {
    const ScratchDir dir;
    const ControlMesh octa = test::octahedron();
    auto write = [&](const std::string& name, const std::string& extra) {
        test::writeText(dir / name, layer(meshPrim("Octa", octa, extra)));
        return (dir / name).string();
    };
    const std::string none = write("none.usda", "    uniform token subdivisionScheme = \"none\"\n");
    const std::string cc = write("cc.usda", "    uniform token subdivisionScheme = \"catmullClark\"\n");
    const std::string plain = write("plain.usda", "");

    BakeOptions flat = smallBake(none);
    flat.level = 2;
    const TranslucentAsset a = bake(flat);
    EXPECT_EQ(a.bake.scheme, "bilinear");
    EXPECT_EQ(a.mesh.faceVertexCounts.size(), 8u * 3u * 4u);  // each triangle: 3 quads, then 4 per level
    for (const Imath::V3f& p : a.mesh.points) EXPECT_NEAR(std::abs(p.x) + std::abs(p.y) + std::abs(p.z), 1.0f, 1e-6f);
    for (std::size_t v = 0; v < a.mesh.points.size(); ++v) {  // interior of a face: the face normal
        const Imath::V3f& p = a.mesh.points[v];
        if (std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) < 1e-3f) continue;
        const Imath::V3f n(std::copysign(1.0f, p.x), std::copysign(1.0f, p.y), std::copysign(1.0f, p.z));
        EXPECT_NEAR(a.mesh.normals[v].dot(n.normalized()), 1.0f, 1e-5f) << "vertex " << v;
    }

    EXPECT_EQ(bake(smallBake(cc)).bake.scheme, "catmullClark");  // triangles: auto alone would pick loop
    EXPECT_EQ(bake(smallBake(plain)).bake.scheme, "loop");
    BakeOptions forced = smallBake(cc);
    forced.scheme = "loop";
    EXPECT_EQ(bake(forced).bake.scheme, "loop");

    // A loop scheme authored on quads is refused, saying where it came from.
    test::writeText(dir / "quads.usda",
                    layer(meshPrim("Cube", test::cube(), "    uniform token subdivisionScheme = \"loop\"\n")));
    try {
        bake(smallBake((dir / "quads.usda").string()));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "Loop subdivision needs triangles")) << e.what();
        EXPECT_TRUE(contains(e.what(), "the file's subdivisionScheme asks for loop; --scheme overrides it")) << e.what();
    }
}

TEST(UsdaMeshImport, TheBakeReportsAMetersPerUnitThatDisagreesWithUnitsPerMm) {
    const ScratchDir dir;
    test::writeText(dir / "cm.usda", layer(meshPrim("Cube", test::cube()), "metersPerUnit = 0.01"));
    BakeReport report;
    BakeOptions options = smallBake((dir / "cm.usda").string());
    options.level = 0;
    bake(options, &report);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0], (dir / "cm.usda").string() +
                                      ": the layer's metersPerUnit 0.01 means 0.1 units per mm, but --units-per-mm "
                                      "is 1; the bake uses --units-per-mm");
    options.unitsPerMm = 0.1;  // agreeing: nothing to say
    report = BakeReport();
    bake(options, &report);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

// ---- refusals -----------------------------------------------------------------------

struct BadLayer {
    const char* what;
    std::string text;
    std::string expected;  // the message after "file:line:column: " (or "file: ")
    std::string at;        // the text the location points at; "" when the message names the file only
};

std::vector<BadLayer> badLayers() {
    const ControlMesh cube = test::cube();
    ControlMesh fewer = cube;
    fewer.faceVertexIndices.pop_back();
    ControlMesh outOfRange = cube;
    outOfRange.faceVertexIndices[5] = 812;
    ControlMesh twoCorners = cube;
    twoCorners.faceVertexCounts = {2, 4, 4, 4, 4, 4, 2};
    const std::string noIndices = "def Mesh \"Cube\"\n{\n    int[] faceVertexCounts = [" + intList(cube.faceVertexCounts) +
                                  "]\n    point3f[] points = [" + pointList(cube.positions) + "]\n}\n";
    std::string floatPoints = meshPrim("Cube", cube);
    floatPoints.replace(floatPoints.find("point3f[]"), 9, "float3[]");
    std::string nanPoint = meshPrim("Cube", cube);
    nanPoint.replace(nanPoint.find("(-0.5, -0.5, -0.5)"), 18, "(nan, -0.5, -0.5)");
    std::string hugePoint = meshPrim("Cube", cube);
    hugePoint.replace(hugePoint.find("(-0.5, -0.5, -0.5)"), 18, "(3.4e38, -0.5, -0.5)");
    const std::string order = "    uniform token[] xformOpOrder = [\"xformOp:shear\"]\n";
    return {
        {"missing faceVertexIndices", layer(noIndices),
         "</Cube>.faceVertexIndices: missing; a Mesh needs points, faceVertexCounts and faceVertexIndices",
         "def Mesh"},
        {"count/index mismatch", layer(meshPrim("Cube", fewer)),
         "</Cube>.faceVertexIndices: 23 indices, but faceVertexCounts add up to 24 corners", "int[] faceVertexIndices"},
        {"out-of-range index", layer(meshPrim("Cube", outOfRange)),
         "</Cube>.faceVertexIndices: index 812 out of range (8 points) at position 5", "int[] faceVertexIndices"},
        {"two-corner face", layer(meshPrim("Cube", twoCorners)),
         "</Cube>.faceVertexCounts: face 0 has 2 corners; a face needs at least 3", "int[] faceVertexCounts"},
        {"NaN point", layer(nanPoint), "non-finite number 'nan' is not accepted", "nan"},
        {"mistyped points", layer(floatPoints), "</Cube>: attribute 'points' has type float3[], expected point3f[]", "float3[]"},
        {"infinite after transform",
         layer(meshPrim("Cube", cube, "    float3 xformOp:scale = (1e38, 1e38, 1e38)\n    float3 xformOp:scale:again = "
                                      "(10, 10, 10)\n    uniform token[] xformOpOrder = [\"xformOp:scale\", "
                                      "\"xformOp:scale:again\"]\n")),
         "</Cube>.points: point 0 (-0.5, -0.5, -0.5) is (-5e+38, -5e+38, -5e+38) after the prim's transform: "
         "5e+39 mm from the origin at the layer's metersPerUnit 0.01, beyond the 1e9 mm (1,000 km) an asset may span",
         "point3f[] points"},
        // Finite floats, but a thousand times the Earth's diameter at USD's default centimetres:
        // such points would overflow ray offsets and sums downstream.
        {"finite but out of range", layer(hugePoint),
         "</Cube>.points: point 0 (3.4e+38, -0.5, -0.5) is (3.4e+38, -0.5, -0.5) after the prim's transform: "
         "3.4e+39 mm from the origin",
         "point3f[] points"},
        {"unknown orientation", layer(meshPrim("Cube", cube, "    uniform token orientation = \"clockwise\"\n")),
         "</Cube>.orientation: 'clockwise' is not one of rightHanded, leftHanded", "uniform token orientation"},
        {"unknown subdivisionScheme", layer(meshPrim("Cube", cube, "    uniform token subdivisionScheme = \"smooth\"\n")),
         "</Cube>.subdivisionScheme: 'smooth' is not one of catmullClark, loop, bilinear, none",
         "uniform token subdivisionScheme"},
        {"unsupported xformOp", layer(meshPrim("Cube", cube, "    float3 xformOp:shear = (1, 0, 0)\n" + order)),
         "</Cube>.xformOpOrder: lists 'xformOp:shear', which is not a supported xformOp", "uniform token[] xformOpOrder"},
        {"op listed, not authored", layer(meshPrim("Cube", cube, "    uniform token[] xformOpOrder = [\"xformOp:scale\"]\n")),
         "</Cube>.xformOpOrder: lists 'xformOp:scale', which the prim does not author with a value", "uniform token[] xformOpOrder"},
        {"unsupported construct", layer("def Xform \"World\" (\n    variantSets = \"look\"\n)\n{\n}\n"),
         "unsupported construct 'variantSets'", "variantSets"},
        {"references", layer("def Xform \"World\" (\n    references = @./cube.usda@\n)\n{\n}\n"),
         "</World>: references are not composed by Opal: flatten the layer first (usdcat --flatten)", "def Xform"},
        {"subLayers", layer(meshPrim("Cube", cube), "subLayers = [@./base.usda@]"),
         "the layer has subLayers (@./base.usda@), which opal-bake does not compose: flatten it first (usdcat --flatten)", ""},
        {"no Mesh prim", layer("def Xform \"World\"\n{\n    def Sphere \"Ball\"\n    {\n    }\n}\n"),
         "the layer has no Mesh prim to bake; not Mesh prims: </World/Ball> (Sphere)", ""},
        {"only an empty Mesh", layer("def Mesh \"Empty\"\n{\n    int[] faceVertexCounts = []\n    int[] faceVertexIndices = "
                                     "[]\n    point3f[] points = []\n}\n"),
         "the layer's Mesh prims have no faces: </Empty>", ""},
        {"not a USDA layer", "PXR-USDC binary", "", ""},
    };
}

TEST(UsdaMeshImport, RefusesMalformedLayersNamingFilePrimAndAttribute) {
    const ScratchDir dir;
    for (const BadLayer& bad : badLayers()) {
        SCOPED_TRACE(bad.what);
        const fs::path path = dir / "bad.usda";
        test::writeText(path, bad.text);
        const std::string error = errorOf(path);
        if (bad.at.empty() && !bad.expected.empty()) {
            EXPECT_EQ(error, path.string() + ": " + bad.expected);
        } else if (!bad.at.empty()) {
            const std::string where = locationOf(path, bad.text, bad.at);
            EXPECT_TRUE(error.starts_with(where + ":")) << "expected at " << where << ": " << error;
            EXPECT_TRUE(contains(error, bad.expected)) << error;
        } else {
            EXPECT_TRUE(error.starts_with(path.string() + ":1:")) << error;  // the reader's own message
        }
    }
}

// Every truncation and a few hundred byte substitutions of a valid layer: each either
// imports or fails with opal::Error, never anything else.
TEST(UsdaMeshImport, NeverFailsOtherwiseThanWithAnErrorOnDamagedFiles) {
    const ScratchDir dir;
    const std::string good =
        layer("def Xform \"W\"\n{\n    double3 xformOp:translate = (1, 2, 3)\n    uniform token[] xformOpOrder = "
              "[\"xformOp:translate\"]\n" +
                  meshPrim("C", test::cube(),
                           "        int[] holeIndices = [2]\n        uniform token orientation = \"leftHanded\"\n"
                           "        quatf xformOp:orient = (1, 0, 0, 0)\n        uniform token[] xformOpOrder = "
                           "[\"!invert!xformOp:orient\"]\n",
                           "    ") +
                  "}\n",
              "metersPerUnit = 0.01");
    std::vector<std::string> variants;  // truncations first: variant n has n bytes
    for (std::size_t n = 0; n < good.size(); ++n) variants.push_back(good.substr(0, n));
    std::mt19937 random(7);
    const std::string alphabet = "0123456789-.,()[]{}<>\"@ \n#=:!eEabcdefghijklmnopqrstuvwxyzXYZ";
    for (int i = 0; i < 300; ++i) {
        std::string v = good;
        for (int k = 0; k < 1 + i % 3; ++k) v[random() % v.size()] = alphabet[random() % alphabet.size()];
        variants.push_back(v);
    }
    std::size_t imported = 0, refused = 0;
    for (std::size_t i = 0; i < variants.size(); ++i) {
        const fs::path path = dir / "damaged.usda";
        test::writeText(path, variants[i]);
        try {
            importMesh(path);
            ++imported;
            // A truncation imports only when it dropped no more than the final newline.
            EXPECT_FALSE(i + 1 < good.size()) << "truncated to " << i << " bytes, yet imported";
        } catch (const Error&) {
            ++refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "variant " << i << " threw a non-opal exception: " << e.what() << "\n" << variants[i];
        }
    }
    EXPECT_EQ(imported + refused, variants.size());
    EXPECT_GT(imported, 0u);  // some substitutions land where they change nothing that matters
}

// ---- the opal-bake executable -------------------------------------------------------

const std::vector<std::string> kSmall = {"--samples", "256", "--level", "1", "--env-res", "8", "--env-terms", "32"};

test::RunResult runBake(std::vector<std::string> args) {
    args.insert(args.begin(), OPAL_BAKE_EXE);
    args.insert(args.end(), kSmall.begin(), kSmall.end());
    test::RunResult r = test::run(args, 180s);
    EXPECT_FALSE(r.timedOut) << test::joined(args) << "\nstderr:\n" << r.err;
    return r;
}

TEST(UsdaMeshImport, CliRefusesBadLayersAndWritesNothing) {
    for (const BadLayer& bad : badLayers()) {
        SCOPED_TRACE(bad.what);
        const ScratchDir dir;
        test::writeText(dir / "bad.usda", bad.text);
        const std::vector<std::string> before = dir.list();
        const test::RunResult r = runBake({(dir / "bad.usda").string(), "-o", (dir / "out").string(), "--json",
                                           (dir / "report.json").string()});
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_TRUE(contains(r.err, "opal-bake: error: " + (dir / "bad.usda").string() + ":")) << r.err;
        EXPECT_TRUE(contains(r.err, bad.expected)) << r.err;
        EXPECT_EQ(dir.list(), before) << "a failed bake must write nothing";
    }
}

TEST(UsdaMeshImport, CliBakesAUsdaCubeAndRebakesItsOwnAsset) {
    const ScratchDir dir;
    test::writeText(dir / "cube.usda", layer(meshPrim("Cube", test::cube())));
    const test::RunResult first = runBake({(dir / "cube.usda").string(), "-o", (dir / "baked").string(), "-q"});
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const test::RunResult second = runBake({(dir / "baked.usda").string(), "-o", (dir / "again").string(), "-q"});
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(dir.list(), (std::vector<std::string>{test::sidecarNamedBy(dir / "again.usda"), "again.usda",
                                                    test::sidecarNamedBy(dir / "baked.usda"), "baked.usda", "cube.usda"}));
}

}  // namespace
}  // namespace opal
