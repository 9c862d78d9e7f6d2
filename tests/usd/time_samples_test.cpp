// Time-sampled attributes: read, evaluated at a time code as USD evaluates one layer
// (held ends, linear between samples, quaternions along the great arc, held types and
// blocks), written back, and refused by readers that have no time.
#include "schema/usd/time_samples.h"
#include "schema/usd/usda_error.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal::usda {
namespace {

Layer read(const std::string& body) { return readUsda("#usda 1.0\ndef \"A\"\n{\n" + body + "}\n", "t.usda"); }

template <ValueType T>
StorageOf<T> at(const Prim& prim, const char* name, double time) {
    const std::optional<Value> v = valueAt(prim.attribute(name), time);
    EXPECT_TRUE(v && !v->isNone()) << name << " at " << time;
    return v->get<T>(name);
}

TEST(TimeSamples, FloatsHoldAtTheEndsAndInterpolateLinearlyBetween) {
    const Layer layer = read(
        "    float x = 7\n"
        "    float x.timeSamples = {\n        10: 4,\n        0: 2,\n        20: -6,\n    }\n");
    const Prim& a = layer.prim("/A");
    EXPECT_EQ(at<types::Float>(a, "x", -5), 2.0f);
    EXPECT_EQ(at<types::Float>(a, "x", 0), 2.0f);
    EXPECT_EQ(at<types::Float>(a, "x", 2.5), 2.5f);
    EXPECT_EQ(at<types::Float>(a, "x", 10), 4.0f);
    EXPECT_EQ(at<types::Float>(a, "x", 15), -1.0f);
    EXPECT_EQ(at<types::Float>(a, "x", 1e9), -6.0f);
    EXPECT_EQ(a.attribute("x").value->get<types::Float>("x"), 7.0f);  // the default is kept beside the samples
    EXPECT_TRUE(mightBeTimeVarying(a));
}

TEST(TimeSamples, TheDeclarationMayFollowItsSamples) {
    const Layer layer = read(
        "    float3 v.timeSamples = {\n        0: (0, 0, 0),\n        4: (4, -8, 2),\n    }\n"
        "    float3 v = (1, 1, 1) (\n        doc = \"after\"\n    )\n");
    const Prim& a = layer.prim("/A");
    ASSERT_EQ(a.properties.size(), 1u);
    EXPECT_EQ(a.attribute("v").metadata.find("doc")->get<types::String>("doc"), "after");
    EXPECT_EQ((at<types::Float3>(a, "v", 1)), (Vec3f{1, -2, 0.5f}));
}

TEST(TimeSamples, MatricesInterpolateComponentwise) {
    const Layer layer = read(
        "    matrix4d m.timeSamples = {\n"
        "        0: ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)),\n"
        "        2: ((3, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (10, -4, 6, 1)),\n    }\n");
    const Matrix4d m = at<types::Matrix4d>(layer.prim("/A"), "m", 0.5);
    EXPECT_DOUBLE_EQ(m[0][0], 1.5);
    EXPECT_DOUBLE_EQ(m[3][0], 2.5);
    EXPECT_DOUBLE_EQ(m[3][1], -1.0);
    EXPECT_DOUBLE_EQ(m[3][2], 1.5);
    EXPECT_DOUBLE_EQ(m[3][3], 1.0);
}

TEST(TimeSamples, QuaternionsTurnAlongTheGreatArc) {
    // Identity to 90 degrees about z: halfway is 45 degrees, (cos 22.5, 0, 0, sin 22.5),
    // where a component-wise lerp would give (0.854, 0, 0, 0.354), not of unit length.
    const double h = std::sqrt(0.5);
    const Layer layer = read("    quatd q.timeSamples = {\n        0: (1, 0, 0, 0),\n        1: (" + std::to_string(h) +
                             ", 0, 0, " + std::to_string(h) + "),\n    }\n");
    const Quatd q = at<types::Quatd>(layer.prim("/A"), "q", 0.5);
    EXPECT_NEAR(q[0], std::cos(std::numbers::pi / 8), 1e-6);
    EXPECT_NEAR(q[3], std::sin(std::numbers::pi / 8), 1e-6);
    EXPECT_NEAR(q[1], 0.0, 1e-12);
}

TEST(TimeSamples, DiscreteTypesAndUnequalArraysHoldTheEarlierSample) {
    const Layer layer = read(
        "    token t.timeSamples = {\n        0: \"off\",\n        10: \"on\",\n    }\n"
        "    int i.timeSamples = {\n        0: 1,\n        10: 3,\n    }\n"
        "    float[] f.timeSamples = {\n        0: [1, 2],\n        10: [3, 4, 5],\n    }\n"
        "    float[] g.timeSamples = {\n        0: [1, 2],\n        10: [3, 4],\n    }\n");
    const Prim& a = layer.prim("/A");
    EXPECT_EQ(at<types::Token>(a, "t", 9.99), "off");
    EXPECT_EQ(at<types::Token>(a, "t", 10), "on");
    EXPECT_EQ(at<types::Int>(a, "i", 5), 1);
    EXPECT_EQ(at<types::FloatArray>(a, "f", 5), (std::vector<float>{1, 2}));
    EXPECT_EQ(at<types::FloatArray>(a, "g", 5), (std::vector<float>{2, 3}));
}

TEST(TimeSamples, ANoneSampleBlocksUntilTheNextSample) {
    const Layer layer = read("    float x.timeSamples = {\n        0: 1,\n        5: None,\n        10: 3,\n    }\n");
    const Attribute& x = layer.prim("/A").attribute("x");
    EXPECT_EQ(valueAt(x, 2.5)->get<types::Float>("x"), 1.0f);  // the span ending in a block holds
    EXPECT_TRUE(valueAt(x, 5)->isNone());
    EXPECT_TRUE(valueAt(x, 7)->isNone());
    EXPECT_EQ(valueAt(x, 10)->get<types::Float>("x"), 3.0f);
}

TEST(TimeSamples, OneSampleIsConstantAndNoSamplesGiveTheDefault) {
    const Layer layer = read("    float x.timeSamples = {\n        3: 2,\n    }\n    float y = 5\n");
    const Prim& a = layer.prim("/A");
    EXPECT_FALSE(mightBeTimeVarying(a));
    EXPECT_EQ(at<types::Float>(a, "x", -100), 2.0f);
    EXPECT_EQ(at<types::Float>(a, "y", 42), 5.0f);
}

TEST(TimeSamples, PropertiesAtATimeAreUntimedAndReadableByTheTypedReaders) {
    const Layer layer = read("    float x.timeSamples = {\n        0: 0,\n        1: 10,\n    }\n    def \"B\"\n    {\n    }\n");
    const Prim& a = layer.prim("/A");
    try {
        (void)a.findValue<types::Float>("x", "prim </A>");
        FAIL() << "a time-sampled attribute read without a time";
    } catch (const UsdaError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "t.usda:5:12: prim </A>: attribute 'x' has timeSamples; Opal reads time-sampled attributes only in "
                  "scenes, at the scene time");
    }
    EXPECT_THROW((void)a.attribute("x").get<types::Float>(), UsdaError);
    const Prim atTime = propertiesAt(a, 0.25);
    EXPECT_EQ(*atTime.findValue<types::Float>("x"), 2.5f);
    EXPECT_TRUE(atTime.children.empty());
    EXPECT_FALSE(mightBeTimeVarying(atTime));
}

TEST(TimeSamples, WrittenLayersReadBackEqual) {
    const Layer layer = read(
        "    custom float x = 7 (\n        doc = \"d\"\n    )\n"
        "    float x.timeSamples = {\n        -1.5: 2,\n        24: None,\n        48: 1e-3,\n    }\n"
        "    color3f c.timeSamples = {\n        0: (1, 0.5, 0.25),\n    }\n");
    const std::string text = writeUsda(layer);
    EXPECT_NE(text.find("float x.timeSamples = {\n        -1.5: 2,\n        24: None,\n        48: 0.001,\n    }"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("color3f c\n"), std::string::npos) << "no empty declaration before samples:\n" << text;
    EXPECT_EQ(readUsda(text, "again.usda"), layer);
}

TEST(TimeSamples, TheWriterRefusesSamplesOfAnotherTypeOrOutOfOrder) {
    Layer layer = read("    float x.timeSamples = {\n        0: 1,\n        1: 2,\n    }\n");
    Attribute& x = std::get<Attribute>(layer.rootPrims[0].properties[0]);
    std::swap(x.timeSamples[0], x.timeSamples[1]);
    EXPECT_THROW(writeUsda(layer), opal::Error);
    std::swap(x.timeSamples[0], x.timeSamples[1]);
    x.timeSamples[1].value = Value::make<types::Double>(2.0);
    EXPECT_THROW(writeUsda(layer), opal::Error);
}

}  // namespace
}  // namespace opal::usda
