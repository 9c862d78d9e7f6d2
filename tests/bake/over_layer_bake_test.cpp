// opal-bake --apply-to (bake/usda_prim_lookup.h, schema/asset/asset_over_layer.h): one Mesh
// prim of a user's layer baked in its own space and written as an over-layer on its path.
// The truth is the plain bake of the same cube alone at the origin: the over-layer, read
// back through the USDA reader, must carry the same mesh and Opal attributes on the user's
// prim path, as over prims, and the asset it names must load. Refusals name
// file:line:column and the prim.
#include "bake/bake_pipeline.h"
#include "bake/mesh_import.h"
#include "schema/asset/asset_layer.h"
#include "schema/error.h"
#include "schema/usd/usda_reader.h"
#include "tests/bake/bake_test_support.h"
#include "tests/bake/over_layer_scenes.h"

#include <gtest/gtest.h>

#include <sstream>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for opal-test-bake"
#endif

namespace opal::over_layer_test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

TranslucentAsset bakeAndWrite(const BakeOptions& options, const fs::path& stem) {
    TranslucentAsset asset = bakeAsset(options, nullptr, CancelToken(), nullptr);
    writeBakedAsset(stem, asset, nullptr, options.applyTo);
    return asset;
}

// The prim's attributes by name, without the two that name the bake (sidecar, identifier).
std::map<std::string, usda::Attribute> bakedAttributes(const usda::Prim& prim) {
    std::map<std::string, usda::Attribute> out;
    for (const usda::Property& p : prim.properties)
        if (const auto* a = std::get_if<usda::Attribute>(&p); a && a->name != "opal:sidecar" && a->name != "opal:bakeId")
            out.emplace(a->name, *a);
    return out;
}

TEST(OverLayerBake, MatchesThePlainBakeOfThePrimOnTheUsersPath) {
    const test::ScratchDir dir;
    test::writeText(dir / "user.usda", test::overLayerUserLayer());
    test::writeText(dir / "Statue.usda", test::overLayerCubeAlone());
    const TranslucentAsset applied = bakeAndWrite(
        test::overLayerBakeOptions((dir / "user.usda").string(), "/World/Statue"), dir / "statue.over");
    bakeAndWrite(test::overLayerBakeOptions((dir / "Statue.usda").string()), dir / "plain");

    const usda::Layer over = usda::readUsdaFile(dir / "statue.over.usda");
    const usda::Layer plain = usda::readUsdaFile(dir / "plain.usda");
    EXPECT_TRUE(over.subLayers.empty());
    EXPECT_EQ(over.defaultPrim(), "");
    ASSERT_EQ(over.rootPrims.size(), 1u);
    const usda::Prim& world = over.rootPrims.front();
    EXPECT_EQ(world.name, "World");
    EXPECT_EQ(world.specifier, usda::Specifier::Over);
    EXPECT_EQ(world.typeName, "");
    EXPECT_TRUE(world.properties.empty()) << "the over-layer must not touch the parent's transform";
    ASSERT_EQ(world.children.size(), 1u);
    const usda::Prim& statue = world.children.front();
    const usda::Prim& asset = plain.prim("/Statue");
    EXPECT_EQ(statue.name, "Statue");
    EXPECT_EQ(statue.specifier, usda::Specifier::Over);
    EXPECT_EQ(statue.typeName, "");
    EXPECT_FALSE(statue.metadata.contains("kind"));
    EXPECT_FALSE(statue.apiSchemas.isExplicit);
    EXPECT_EQ(statue.apiSchemas.prepended, std::vector<std::string>{"OpalSubsurfaceAPI"});
    EXPECT_TRUE(statue.children.empty());

    // Every attribute of the plain asset's prim, value for value (the mesh in the prim's own
    // space: neither the Mesh's scale nor the Xform's transform baked in), and nothing else.
    auto mine = bakedAttributes(statue);
    const auto theirs = bakedAttributes(asset);
    // ... but for holeIndices, emptied: the user's would index the control mesh's faces.
    ASSERT_TRUE(mine.count("holeIndices"));
    EXPECT_TRUE(mine.at("holeIndices").get<usda::types::IntArray>().empty());
    mine.erase("holeIndices");
    std::vector<std::string> names, expected;
    for (const auto& [name, a] : mine) names.push_back(name);
    for (const auto& [name, a] : theirs) expected.push_back(name);
    EXPECT_EQ(names, expected);
    for (const auto& [name, a] : theirs) {
        const auto it = mine.find(name);
        if (it == mine.end()) continue;
        EXPECT_TRUE(it->second == a) << name << " differs from the plain asset's";
    }
    EXPECT_EQ(statue.findValue<usda::types::Token>("subdivisionScheme") ? *statue.findValue<usda::types::Token>("subdivisionScheme") : "",
              "none");
    EXPECT_TRUE(statue.findAttribute("primvars:displayColor"));
    EXPECT_EQ(statue.findAttribute("xformOp:scale"), nullptr);

    // The prim, as it stands, loads with its sidecar: the same asset, named as the prim.
    const TranslucentAsset loaded = readAsset(statue, dir / "statue.over.usda");
    EXPECT_EQ(loaded.name, "Statue");
    EXPECT_EQ(loaded.mesh.points, applied.mesh.points);
    EXPECT_EQ(loaded.samples.size(), 256u);
}

TEST(OverLayerBake, TheIdentifierDiffersFromThePlainBakes) {
    // The layers differ, so the bake identifiers must too, though the mesh is the same.
    const test::ScratchDir dir;
    test::writeText(dir / "user.usda", test::overLayerUserLayer());
    test::writeText(dir / "Statue.usda", test::overLayerCubeAlone());
    const TranslucentAsset a = bakeAndWrite(test::overLayerBakeOptions((dir / "user.usda").string(), "/World/Statue"),
                                            dir / "a");
    const TranslucentAsset b = bakeAndWrite(test::overLayerBakeOptions((dir / "Statue.usda").string()), dir / "b");
    ASSERT_TRUE(a.bake.identifier && b.bake.identifier);
    EXPECT_NE(*a.bake.identifier, *b.bake.identifier);
    EXPECT_EQ(a.mesh.points, b.mesh.points);
}

// ---- refusals -------------------------------------------------------------------------

std::string errorOf(const fs::path& file, const std::string& primPath) {
    try {
        importMeshPrim(file, primPath);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// "file:line:column" of the first line holding `needle`, at its first non-blank column.
std::string lineOf(const fs::path& file, const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
        if (line.find(needle) != std::string::npos)
            return file.string() + ":" + std::to_string(number) + ":" +
                   std::to_string(line.find_first_not_of(' ') + 1);
    return "(not found)";
}

TEST(OverLayerBake, RefusalsNameFileLineColumnAndPrim) {
    const test::ScratchDir dir;
    const std::string text = test::overLayerUserLayer();
    const fs::path file = dir / "user.usda";
    test::writeText(file, text);
    struct Case {
        std::string path, expected;
    };
    const Case cases[] = {
        {"/World/Missing", lineOf(file, text, "def Xform \"World\"") + ": </World>: has no child prim 'Missing'"},
        {"/World", lineOf(file, text, "def Xform \"World\"") + ": </World>: is a Xform prim, not a Mesh"},
        {"/World/Props", lineOf(file, text, "def Scope \"Props\"") + ": </World/Props>: is a Scope prim, not a Mesh"},
        {"/World/Template/Shape", lineOf(file, text, "class \"Template\"") + ": </World/Template>: is a class prim"},
        {"/World/Retired", lineOf(file, text, "def Mesh \"Retired\"") + ": </World/Retired>: is inactive"},
        {"/Nowhere/Statue", file.string() + ": --apply-to </Nowhere/Statue>: the layer has no root prim 'Nowhere'"},
        {"World/Statue", file.string() + ": --apply-to <World/Statue>: not an absolute prim path"},
        {"/World//Statue", file.string() + ": --apply-to </World//Statue>: an empty prim name"},
    };
    for (const Case& c : cases) EXPECT_EQ(errorOf(file, c.path).rfind(c.expected, 0), 0u) << errorOf(file, c.path);
    // The control: the prim itself imports, untransformed (its 8 control points as authored).
    EXPECT_EQ(importMeshPrim(file, "/World/Statue").mesh.positions.front(), Imath::V3f(-5, -5, -5));

    // An over of the prim (in a layer of its own it defines nothing).
    const std::string overText = "#usda 1.0\n\nover \"World\"\n{\n    def Mesh \"Statue\"\n    {\n" +
                                 test::overLayerCubeBody() + "    }\n}\n";
    test::writeText(dir / "over.usda", overText);
    EXPECT_EQ(errorOf(dir / "over.usda", "/World/Statue")
                  .rfind(lineOf(dir / "over.usda", overText, "over \"World\"") + ": </World>: is an over prim", 0),
              0u)
        << errorOf(dir / "over.usda", "/World/Statue");
}

TEST(OverLayerBake, TheCommandLineWritesTheOverLayerAndRefusesOtherInputs) {
    const test::ScratchDir dir;
    test::writeText(dir / "user.usda", test::overLayerUserLayer());
    const auto run = [](std::vector<std::string> args) {
        args.insert(args.begin(), OPAL_BAKE_EXE);
        return test::run(args, 120s);
    };
    const test::RunResult ok = run({(dir / "user.usda").string(), "--apply-to", "/World/Statue", "-o",
                                    (dir / "statue.over").string(), "--samples", "256", "-q"});
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_EQ(usda::readUsdaFile(dir / "statue.over.usda").prim("/World/Statue").specifier, usda::Specifier::Over);

    const test::RunResult retired = run({(dir / "user.usda").string(), "--apply-to", "/World/Retired", "-o",
                                         (dir / "x").string(), "--samples", "256", "-q"});
    EXPECT_EQ(retired.exitCode, 1);
    EXPECT_NE(retired.err.find("user.usda:"), std::string::npos) << retired.err;
    EXPECT_NE(retired.err.find("</World/Retired>: is inactive"), std::string::npos) << retired.err;
    const test::RunResult builtin = run({"builtin:candle", "--apply-to", "/candle", "-o", (dir / "y").string(), "-q"});
    EXPECT_EQ(builtin.exitCode, 1) << builtin.err;
    const test::RunResult farm = run({(dir / "user.usda").string(), "--apply-to", "/World/Statue", "-o",
                                      (dir / "z").string(), "--farm", "local"});
    EXPECT_EQ(farm.exitCode, 2) << farm.err;
    EXPECT_NE(farm.err.find("--apply-to"), std::string::npos) << farm.err;
    EXPECT_FALSE(fs::exists(dir / "x.usda") || fs::exists(dir / "y.usda") || fs::exists(dir / "z.usda"));
}

}  // namespace
}  // namespace opal::over_layer_test
