// The writer refuses models it could not read back, names what is wrong, and replaces
// files atomically; large arrays parse quickly and exactly.
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace opal::usda {
namespace {

std::string writeError(const Layer& layer) {
    try {
        writeUsda(layer);
    } catch (const opal::Error& e) {
        return e.what();
    }
    return "(no error)";
}

Layer withPrim(Prim prim) {
    Layer layer;
    layer.addRootPrim(std::move(prim));
    return layer;
}

TEST(UsdaWriter, RejectsWhatItCouldNotReadBack) {
    Prim nan{.name = "A"};
    nan.addAttribute("x", Value::make<types::Float3>({0, std::numeric_limits<float>::quiet_NaN(), 0}));
    EXPECT_EQ(writeError(withPrim(nan)),
              "cannot write attribute /A.x: non-finite number (USDA as Opal writes it carries finite numbers only)");

    EXPECT_EQ(writeError(withPrim(Prim{.name = "a b"})), "cannot write USDA: /a b: prim name is not an identifier");

    Prim badProperty{.name = "A"};
    badProperty.addAttribute("x y", Value::make<types::Int>(1));
    EXPECT_EQ(writeError(withPrim(badProperty)),
              "cannot write USDA: /A.x y: property name is not a (namespaced) identifier");

    Prim badMetadata{.name = "A"};
    badMetadata.metadata.set("kind", Value::string("component"));
    EXPECT_EQ(writeError(withPrim(badMetadata)), "cannot write USDA: /A: metadata 'kind' must have type token");

    Prim unknownMetadata{.name = "A"};
    unknownMetadata.metadata.set("payload", Value::asset("x.usda"));
    EXPECT_EQ(writeError(withPrim(unknownMetadata)),
              "cannot write USDA: /A: 'payload' is not prim metadata in Opal's USDA subset");

    Prim badTarget{.name = "A"};
    badTarget.addRelationship("r", {"/a//b"});
    EXPECT_EQ(writeError(withPrim(badTarget)), "cannot write USDA: /A.r: invalid path </a//b>");

    Prim inheritsOnDef{.name = "A", .inherits = "/B"};
    EXPECT_EQ(writeError(withPrim(inheritsOnDef)), "cannot write USDA: /A: inherits is written only on class prims");

    Prim mismatch{.name = "A"};
    mismatch.addAttribute("x", Value::make<types::Int>(1));
    std::get<Attribute>(mismatch.properties.back()).type = types::Float;
    EXPECT_EQ(writeError(withPrim(mismatch)),
              "cannot write USDA: /A.x: attribute type float does not match its value of type int");

    Prim duplicate{.name = "A"};
    duplicate.children = {Prim{.name = "B"}, Prim{.name = "B"}};
    EXPECT_EQ(writeError(withPrim(duplicate)), "cannot write USDA: /A/B: duplicate prim name");
}

TEST(UsdaWriter, BuildersRejectDuplicates) {
    Prim prim{.name = "A"};
    prim.addAttribute("x", Value::make<types::Int>(1));
    EXPECT_THROW(prim.addRelationship("x", {}), opal::Error);
    prim.addChild(Prim{.name = "B"});
    EXPECT_THROW(prim.addChild(Prim{.name = "B"}), opal::Error);
}

class UsdaFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::path(OPAL_BINARY_DIR) / "test-usda-files" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    std::filesystem::path dir_;
};

TEST_F(UsdaFileTest, WritesAtomicallyAndReadsBack) {
    Prim prim{.typeName = "Mesh", .name = "Asset"};
    prim.addAttribute("points", Value::make<types::Point3fArray>({{1, 2, 3}}));
    Layer layer = withPrim(prim);
    std::filesystem::path path = dir_ / "asset.usda";
    writeUsdaFile(path, layer);
    writeUsdaFile(path, layer);  // replacing an existing file
    EXPECT_TRUE(readUsdaFile(path) == layer);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), std::filesystem::directory_iterator()), 1)
        << "temporary files left behind";
    try {
        readUsda(writeUsda(layer) + "}", "x");
    } catch (const UsdaError& e) {
        EXPECT_EQ(*e.where().file, "x");
    }
}

TEST_F(UsdaFileTest, ErrorsNameThePath) {
    std::filesystem::path path = dir_ / "missing-dir" / "asset.usda";
    try {
        writeUsdaFile(path, Layer{});
        FAIL() << "no error";
    } catch (const opal::Error& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with(path.string() + ": cannot write file")) << e.what();
    }
    try {
        writeUsdaFile(dir_ / "bad.usda", withPrim(Prim{.name = "a b"}));
        FAIL() << "no error";
    } catch (const opal::Error& e) {
        EXPECT_EQ(std::string(e.what()), (dir_ / "bad.usda").string() + ": cannot write USDA: /a b: prim name is not an identifier");
    }
    EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.usda"));
    std::ofstream(dir_ / "broken.usda") << "#usda 1.0\ndef \"A\" {\n    half h = 1\n}\n";
    try {
        readUsdaFile(dir_ / "broken.usda");
        FAIL() << "no error";
    } catch (const UsdaError& e) {
        EXPECT_EQ(std::string(e.what()), (dir_ / "broken.usda").string() +
                                             ":3:5: unknown or unsupported attribute type 'half' (Opal's USDA subset: "
                                             "see schema/usd/SUBSET.md)");
    }
}

// 300k floats as 100k points: parses exactly (no timing assertion; see the test time).
TEST(UsdaLarge, ParsesAThreeHundredThousandFloatArray) {
    constexpr int kPoints = 100000;
    std::string text = "#usda 1.0\ndef Mesh \"M\"\n{\n    point3f[] points = [";
    for (int i = 0; i < kPoints; ++i) {
        text += (i > 0 ? ", (" : "(") + std::to_string(i) + ".25, -" + std::to_string(i % 977) + ".5, 1e-3)";
    }
    text += "]\n}\n";
    Layer layer = readUsda(text, "big.usda");
    const std::vector<Vec3f>& points = layer.prim("/M").attribute("points").get<types::Point3fArray>();
    ASSERT_EQ(points.size(), static_cast<std::size_t>(kPoints));
    for (int i = 0; i < kPoints; i += 997) {
        EXPECT_EQ(points[i], (Vec3f{i + 0.25f, -(i % 977) - 0.5f, 1e-3f})) << i;
    }
    EXPECT_TRUE(readUsda(writeUsda(layer), "big2.usda") == layer);
}

}  // namespace
}  // namespace opal::usda
