// Typed access with clear errors, number formatting (independent expected strings and
// bit-exact round trips), string and asset-path quoting as Sdf does it.
#include "schema/usd/usda_error.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_syntax.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>

namespace opal::usda {
namespace {

const Layer& sample() {
    static const Layer layer = readUsda(R"(#usda 1.0
(
    defaultPrim = "Asset"
    metersPerUnit = 0.001
)

def Mesh "Asset" (
    prepend apiSchemas = ["OpalSubsurfaceAPI"]
    customData = {
        string libraryName = "opal"
    }
    kind = "component"
)
{
    float3[] points = [(0, 0, 0)]
    float blocked = None
    double declared
    rel material:binding = [</A>, </B>]

    def Scope "Child"
    {
    }
}
)",
                                        "sample.usda");
    return layer;
}

std::string errorOf(auto&& f) {
    try {
        f();
    } catch (const opal::Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(UsdaValue, TypedAccessReturnsTheStoredData) {
    const Prim& asset = sample().prim("/Asset");
    const std::vector<Vec3f>& points = asset.attribute("points").get<types::Float3Array>();
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(points[0], (Vec3f{0, 0, 0}));
    EXPECT_EQ(sample().defaultPrim(), "Asset");
    EXPECT_EQ(sample().metersPerUnit(), 0.001);
    EXPECT_EQ(asset.kind(), "component");
    EXPECT_TRUE(asset.hasApiSchema("OpalSubsurfaceAPI"));
    EXPECT_FALSE(asset.hasApiSchema("MaterialBindingAPI"));
    EXPECT_EQ(asset.customData()->find("libraryName")->get<types::String>("libraryName"), "opal");
    EXPECT_EQ(&sample().prim("/Asset/Child"), &asset.child("Child"));
    EXPECT_EQ(sample().findPrim("/Asset/Nope"), nullptr);
    EXPECT_EQ(sample().findPrim("Asset"), nullptr);
    EXPECT_EQ(sample().findPrim("/Asset/"), nullptr);
    EXPECT_EQ(sample().findPrim("//Asset"), nullptr);
    EXPECT_EQ(sample().findPrim("/"), nullptr);
    EXPECT_EQ(sample().findPrim("/Asset/Child"), &sample().rootPrims[0].children[0]);
}

TEST(UsdaValue, WrongTypeNamesTheLocationAndBothTypes) {
    const Prim& asset = sample().prim("/Asset");
    EXPECT_EQ(errorOf([&] { asset.attribute("points").get<types::Point3fArray>(); }),
              "sample.usda:15:5: attribute 'points' has type float3[], expected point3f[]");
    EXPECT_EQ(errorOf([&] { asset.attribute("blocked").get<types::Float>(); }),
              "sample.usda:16:5: attribute 'blocked' is None (blocked), expected a float");
    EXPECT_EQ(errorOf([&] { asset.attribute("declared").get<types::Double>(); }),
              "sample.usda:17:5: attribute 'declared' has no value, expected double");
    EXPECT_EQ(errorOf([&] { asset.attribute("normals"); }), "sample.usda:7:1: prim 'Asset' has no attribute 'normals'");
    EXPECT_EQ(errorOf([&] { asset.relationship("material:binding").target(); }),
              "sample.usda:18:5: relationship 'material:binding' has 2 targets, expected exactly one");
    EXPECT_EQ(errorOf([&] { asset.customData()->find("libraryName")->get<types::Token>("customData 'libraryName'"); }),
              "sample.usda:10:30: customData 'libraryName' has type string, expected token");
    EXPECT_EQ(errorOf([&] { sample().prim("/Missing"); }), "sample.usda: no prim at path '/Missing'");
}

TEST(UsdaValue, FindValueReadsAnAuthoredValueOfAnAcceptedType) {
    const Prim& asset = sample().prim("/Asset");
    const std::vector<Vec3f>* points = asset.findValue<types::Float3Array>("points");
    ASSERT_NE(points, nullptr);
    EXPECT_EQ(*points, (std::vector<Vec3f>{{0, 0, 0}}));
    const ValueType eitherArray[] = {types::Point3fArray, types::Float3Array};
    EXPECT_EQ(asset.findValue("points", eitherArray), asset.findAttribute("points"));
    // Absent, blocked and declared-only attributes hold no value.
    EXPECT_EQ(asset.findValue<types::Float3Array>("normals"), nullptr);
    EXPECT_EQ(asset.findValue<types::Float>("blocked"), nullptr);
    EXPECT_EQ(asset.findValue<types::Double>("declared"), nullptr);
}

TEST(UsdaValue, FindValueNamesTheAttributeTheTypesAndTheCallersPrim) {
    const Prim& asset = sample().prim("/Asset");
    EXPECT_EQ(errorOf([&] { asset.findValue<types::Point3fArray>("points"); }),
              "sample.usda:15:5: attribute 'points' has type float3[], expected point3f[]");
    const ValueType reals[] = {types::Float, types::Double};
    EXPECT_EQ(errorOf([&] { asset.findValue("points", reals, "Mesh </Asset>"); }),
              "sample.usda:15:5: Mesh </Asset>: attribute 'points' has type float3[], expected float or double");
    // Declared with another type but without a value is still an error: the file is wrong.
    EXPECT_EQ(errorOf([&] { asset.findValue<types::Float>("declared"); }),
              "sample.usda:17:5: attribute 'declared' has type double, expected float");
    EXPECT_EQ(errorOf([&] { asset.findValue<types::Token>("material:binding", "Mesh </Asset>"); }),
              "sample.usda:18:5: Mesh </Asset>: 'material:binding' is a relationship, expected an attribute of "
              "type token");
}

TEST(UsdaValue, TypeNamesRoundTrip) {
    for (auto scalar = static_cast<int>(ScalarType::Bool); scalar < static_cast<int>(ScalarType::Dictionary); ++scalar) {
        for (bool isArray : {false, true}) {
            ValueType type{static_cast<ScalarType>(scalar), isArray};
            EXPECT_EQ(parseTypeName(typeName(type)), type) << typeName(type);
        }
    }
    EXPECT_EQ(parseTypeName("half"), std::nullopt);
    EXPECT_EQ(parseTypeName("dictionary[]"), std::nullopt);
    EXPECT_EQ(typeName(types::Point3fArray), "point3f[]");
}

template <class T>
std::string formatted(T v) {
    std::string out;
    appendNumber(out, v);
    return out;
}

TEST(UsdaValue, NumbersUseTheShortestRoundTripText) {
    EXPECT_EQ(formatted(0.1f), "0.1");
    EXPECT_EQ(formatted(0.1), "0.1");
    EXPECT_EQ(formatted(1.3f), "1.3");
    EXPECT_EQ(formatted(100.0), "100");
    EXPECT_EQ(formatted(-0.0), "-0");
    EXPECT_EQ(formatted(123.456), "123.456");
    EXPECT_EQ(formatted(1e-6), "0.000001");
    EXPECT_EQ(formatted(1e-7), "1e-7");
    EXPECT_EQ(formatted(2.5e-7f), "2.5e-7");
    EXPECT_EQ(formatted(1e20), "100000000000000000000");
    EXPECT_EQ(formatted(1e21), "1e+21");
    EXPECT_EQ(formatted(3.4028235e38f), "3.4028235e+38");
    EXPECT_EQ(formatted(1e-45f), "1e-45");
    EXPECT_EQ(formatted(5e-324), "5e-324");
    EXPECT_EQ(formatted(std::int64_t{-42}), "-42");
    EXPECT_EQ(formatted(std::uint64_t{18446744073709551615u}), "18446744073709551615");
}

// Random bit patterns (finite ones) written and read back must be bit-identical.
TEST(UsdaValue, FloatsAndDoublesRoundTripBitExactly) {
    std::mt19937_64 rng(20240601);
    Prim prim{.name = "N"};
    std::vector<float> floats;
    std::vector<double> doubles;
    while (floats.size() < 20000) {
        auto f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
        auto d = std::bit_cast<double>(rng());
        if (std::isfinite(f)) {
            floats.push_back(f);
        }
        if (std::isfinite(d)) {
            doubles.push_back(d);
        }
    }
    prim.addAttribute("f", Value::make<types::FloatArray>(floats));
    prim.addAttribute("d", Value::make<types::DoubleArray>(doubles));
    Layer layer;
    layer.addRootPrim(prim);
    Layer read = readUsda(writeUsda(layer), "numbers.usda");
    const auto& readFloats = read.prim("/N").attribute("f").get<types::FloatArray>();
    const auto& readDoubles = read.prim("/N").attribute("d").get<types::DoubleArray>();
    ASSERT_EQ(readFloats.size(), floats.size());
    ASSERT_EQ(readDoubles.size(), doubles.size());
    for (std::size_t i = 0; i < floats.size(); ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(readFloats[i]), std::bit_cast<std::uint32_t>(floats[i])) << i;
    }
    for (std::size_t i = 0; i < doubles.size(); ++i) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(readDoubles[i]), std::bit_cast<std::uint64_t>(doubles[i])) << i;
    }
}

TEST(UsdaValue, NumberSpellingsReadAsExpected) {
    Layer layer = readUsda("#usda 1.0\ndef \"N\" {\n double[] d = [1., .5, -.5, 1E3, 1e+2, 2.50e-1, 007]\n}\n", "n.usda");
    EXPECT_EQ(layer.prim("/N").attribute("d").get<types::DoubleArray>(),
              (std::vector<double>{1, 0.5, -0.5, 1000, 100, 0.25, 7}));
}

TEST(UsdaValue, StringsAreQuotedAsSdfQuotesThem) {
    EXPECT_EQ(quoteString("plain"), "\"plain\"");
    EXPECT_EQ(quoteString("say \"hi\""), "'say \"hi\"'");
    EXPECT_EQ(quoteString("both \" and '"), "\"both \\\" and '\"");
    EXPECT_EQ(quoteString("two\nlines"), "\"\"\"two\nlines\"\"\"");
    EXPECT_EQ(quoteString("tab\there\r"), "\"tab\\there\\r\"");
    EXPECT_EQ(quoteString("back\\slash"), "\"back\\\\slash\"");
    EXPECT_EQ(quoteString("\x01"), "\"\\x01\"");
    EXPECT_EQ(quoteString("caf\xc3\xa9"), "\"caf\xc3\xa9\"");
    EXPECT_EQ(quoteString("lone \xe9 byte"), "\"lone \\xe9 byte\"");
    EXPECT_EQ(quoteAssetPath("./a.usda"), "@./a.usda@");
    EXPECT_EQ(quoteAssetPath("a@b"), "@@@a@b@@@");
    EXPECT_EQ(quoteAssetPath("a@@@b"), "@@@a\\@@@b@@@");
}

TEST(UsdaValue, EscapesReadBack) {
    Layer layer = readUsda(
        "#usda 1.0\ndef \"S\" {\n string[] s = [\"a\\tb\", 'q\\'s', \"\\x41\\101\\xc3\\xa9\", \"\"\"x\n\\\"y\"\"\"]\n"
        " asset[] a = [@@@a\\@@@b@@@, @@@c@@@@, @@@d@@@]\n}\n",
        "s.usda");
    EXPECT_EQ(layer.prim("/S").attribute("s").get<types::StringArray>(),
              (std::vector<std::string>{"a\tb", "q's", "AA\xc3\xa9", "x\n\"y"}));
    EXPECT_EQ(layer.prim("/S").attribute("a").get<types::AssetArray>(),
              (std::vector<std::string>{"a@@@b", "c@", "d"}));
}

TEST(UsdaValue, PathsAndNamesFollowSdfSyntax) {
    EXPECT_TRUE(isPath("/World/Mesh"));
    EXPECT_TRUE(isPath("/World/Mesh.points"));
    EXPECT_TRUE(isPath("/World/Mesh.primvars:st"));
    EXPECT_TRUE(isPath("../Sibling"));
    EXPECT_TRUE(isPath("Child/Grandchild"));
    EXPECT_TRUE(isPath(".."));
    EXPECT_FALSE(isPath("/"));
    EXPECT_FALSE(isPath(""));
    EXPECT_FALSE(isPath("/a//b"));
    EXPECT_FALSE(isPath("/a/"));
    EXPECT_FALSE(isPath("/A{v=x}"));
    EXPECT_FALSE(isPath("/A.rel[/B]"));
    EXPECT_TRUE(isNamespacedName("opal:basis:K"));
    EXPECT_FALSE(isNamespacedName("opal::K"));
    EXPECT_FALSE(isNamespacedName("1a"));
    EXPECT_FALSE(isIdentifier("a:b"));
}

TEST(UsdaValue, DictionaryKeepsKeysSortedAndUnique) {
    Dictionary d;
    EXPECT_TRUE(d.insert("b", Value::token("1")));
    EXPECT_TRUE(d.insert("a", Value::token("2")));
    EXPECT_FALSE(d.insert("a", Value::token("3")));
    d.set("a", Value::token("4"));
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d.entries()[0].key, "a");
    EXPECT_EQ(d.find("a")->get<types::Token>("a"), "4");
    EXPECT_TRUE(d.erase("b"));
    EXPECT_FALSE(d.contains("b"));
}

}  // namespace
}  // namespace opal::usda
