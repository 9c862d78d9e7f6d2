// Round trips: a rich layer built in code must write exactly the hand-written canonical
// text below; reading that text gives the same model; write -> read -> write is
// byte-identical; a messy hand-written spelling of the same layer reads to the same model.
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

namespace opal::usda {
namespace {

// Everything in Opal's subset, in the canonical form the writer produces.
constexpr std::string_view kCanonical = R"USDA(#usda 1.0
(
    "Opal round-trip test layer"
    customLayerData = {
        string creator = "opal-test"
        dictionary opal = {
            int version = 1
        }
    }
    defaultPrim = "World"
    doc = """A layer that uses
every construct of the subset."""
    endTimeCode = 10
    metersPerUnit = 0.01
    startTimeCode = 1
    subLayers = [
        @./base.usda@,
        @@@odd@name.usda@@@
    ]
    upAxis = "Y"
)

def Xform "World" (
    kind = "assembly"
)
{
    double3 xformOp:translate = (0, 1.5, -2)
    matrix4d xformOp:transform = ( (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (2, 3, 4, 1) )
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:transform"]

    def Mesh "Candle" (
        prepend apiSchemas = ["OpalSubsurfaceAPI"]
        append apiSchemas = ["MaterialBindingAPI"]
        customData = {
            bool baked = 1
            string "key with spaces" = "x"
            double[] weights = [0.25, 0.75]
        }
        doc = "The wax body."
        instanceable = false
        prepend references = @./candle_baked.usda@</Asset>
    )
    {
        int[] faceVertexCounts = [3, 3]
        int[] faceVertexIndices = [0, 1, 2, 0, 2, 3]
        rel material:binding = </World/Looks/Wax>
        normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1)] (
            interpolation = "vertex"
        )
        float opal:eta = 1.3 (
            doc = "Relative index of refraction (unitless)."
        )
        color3f opal:sigmaA = (0.0021, 0.0041, 0.0071)
        asset opal:sidecar = @./candle.opal@
        point3f[] points = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
        texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (
            interpolation = "faceVarying"
        )
    }

    def Scope "Looks"
    {
        def Material "Wax"
        {
        }
    }
}

def "Values" (
    "a bare comment"
)
{
    custom bool b = 1
    bool[] bools = [1, 0]
    custom uniform float blocked = None
    color4f c4 = (0.1, 0.2, 0.3, 1)
    double d = 1e-7
    double2 d2 = (1.5e+25, -0)
    double3[] d3 = []
    double4 d4 = (100000000000000000000, 1e+21, 0.000001, 5e-324)
    float f = 3.4028235e+38
    float2 f2 = (0.1, -0.5)
    float4 f4 = (1, 2, 3, 4)
    int i = -2147483648
    int2 i2 = (1, -1)
    int3 i3 = (1, 2, 3)
    int4 i4 = (1, 2, 3, 4)
    int64 i64 = -9223372036854775808
    matrix4d[] matrices = [( (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1) )]
    float nothing
    quatf q = (1, 0, 0, 0)
    rel rels = [
        </World/Looks>,
        </World/Candle.points>,
    ]
    rel unset
    string s = 'say "hi"'
    string[] strings = ["a", """multi
line \\ \t \x01 é"""]
    string tripled = """two
lines"""
    token t = "component"
    uint u = 4294967295
    uint64 u64 = 18446744073709551615
    vector3d v = (1, 0, 0) (
        customData = {
            dictionary nested = {
                dictionary deeper = {
                    asset file = @./x.usda@
                }
            }
        }
        displayName = "Direction"
        hidden = true
    )
}

class "SchemaLike" (
    inherits = </APISchemaBase>
)
{
    rel none = None
}

over "Override" (
    references = [
        @./a.usda@,
        </World>
    ]
)
{
}
)USDA";

Value doubles(std::vector<double> v) { return Value::make<types::DoubleArray>(std::move(v)); }

Layer layerHeader() {
    Layer layer;
    layer.comment = "Opal round-trip test layer";
    Dictionary opal;
    opal.set("version", Value::make<types::Int>(1));
    Dictionary custom;
    custom.set("opal", Value::dictionary(opal));
    custom.set("creator", Value::string("opal-test"));
    layer.metadata.set("upAxis", Value::token("Y"));
    layer.metadata.set("metersPerUnit", Value::make<types::Double>(0.01));
    layer.metadata.set("defaultPrim", Value::token("World"));
    layer.metadata.set("doc", Value::string("A layer that uses\nevery construct of the subset."));
    layer.metadata.set("customLayerData", Value::dictionary(custom));
    layer.metadata.set("startTimeCode", Value::make<types::Double>(1));
    layer.metadata.set("endTimeCode", Value::make<types::Double>(10));
    layer.subLayers = {"./base.usda", "odd@name.usda"};
    return layer;
}

Prim candle() {
    Prim mesh{.typeName = "Mesh", .name = "Candle"};
    mesh.apiSchemas.prepended = {"OpalSubsurfaceAPI"};
    mesh.apiSchemas.appended = {"MaterialBindingAPI"};
    mesh.references.prepended = {Reference{.assetPath = "./candle_baked.usda", .primPath = "/Asset"}};
    mesh.metadata.set("doc", Value::string("The wax body."));
    mesh.metadata.set("instanceable", Value::make<types::Bool>(false));
    Dictionary data;
    data.set("baked", Value::make<types::Bool>(true));
    data.set("weights", doubles({0.25, 0.75}));
    data.set("key with spaces", Value::string("x"));
    mesh.metadata.set("customData", Value::dictionary(data));
    mesh.addAttribute("faceVertexCounts", Value::make<types::IntArray>({3, 3}));
    mesh.addAttribute("faceVertexIndices", Value::make<types::IntArray>({0, 1, 2, 0, 2, 3}));
    mesh.addRelationship("material:binding", {"/World/Looks/Wax"});
    mesh.addAttribute("normals", Value::make<types::Normal3fArray>({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}))
        .metadata.set("interpolation", Value::token("vertex"));
    mesh.addAttribute("opal:eta", Value::make<types::Float>(1.3f))
        .metadata.set("doc", Value::string("Relative index of refraction (unitless)."));
    mesh.addAttribute("opal:sigmaA", Value::make<types::Color3f>({0.0021f, 0.0041f, 0.0071f}));
    mesh.addAttribute("opal:sidecar", Value::asset("./candle.opal"));
    mesh.addAttribute("points", Value::make<types::Point3fArray>({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}));
    mesh.addAttribute("primvars:st", Value::make<types::TexCoord2fArray>({{0, 0}, {1, 0}, {1, 1}, {0, 1}}))
        .metadata.set("interpolation", Value::token("faceVarying"));
    return mesh;
}

Prim world() {
    Prim prim{.typeName = "Xform", .name = "World"};
    prim.metadata.set("kind", Value::token("assembly"));
    prim.addAttribute("xformOp:translate", Value::make<types::Double3>({0, 1.5, -2}));
    prim.addAttribute("xformOp:transform",
                      Value::make<types::Matrix4d>({{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {2, 3, 4, 1}}}));
    prim.addAttribute("xformOpOrder", Value::make<types::TokenArray>({"xformOp:translate", "xformOp:transform"}), true);
    prim.addChild(candle());
    Prim looks{.typeName = "Scope", .name = "Looks"};
    looks.addChild(Prim{.typeName = "Material", .name = "Wax"});
    prim.addChild(looks);
    return prim;
}

void addScalars(Prim& prim) {
    prim.addAttribute("b", Value::make<types::Bool>(true));
    std::get<Attribute>(prim.properties.back()).custom = true;
    prim.addAttribute("bools", Value::make<types::BoolArray>({true, false}));
    Attribute& blocked = prim.addAttribute("blocked", Value::none(types::Float), true);
    blocked.custom = true;
    prim.addAttribute("c4", Value::make<types::Color4f>({0.1f, 0.2f, 0.3f, 1}));
    prim.addAttribute("d", Value::make<types::Double>(1e-7));
    prim.addAttribute("d2", Value::make<types::Double2>({1.5e25, -0.0}));
    prim.addAttribute("d3", Value::make<types::Double3Array>({}));
    prim.addAttribute("d4", Value::make<types::Double4>({1e20, 1e21, 1e-6, 5e-324}));
    prim.addAttribute("f", Value::make<types::Float>(3.4028235e+38f));
    prim.addAttribute("f2", Value::make<types::Float2>({0.1f, -0.5f}));
    prim.addAttribute("f4", Value::make<types::Float4>({1, 2, 3, 4}));
    prim.addAttribute("i", Value::make<types::Int>(-2147483647 - 1));
    prim.addAttribute("i2", Value::make<types::Int2>({1, -1}));
    prim.addAttribute("i3", Value::make<types::Int3>({1, 2, 3}));
    prim.addAttribute("i4", Value::make<types::Int4>({1, 2, 3, 4}));
    prim.addAttribute("i64", Value::make<types::Int64>(INT64_MIN));
    prim.addAttribute("matrices",
                      Value::make<types::Matrix4dArray>({{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}}));
}

void addTheRest(Prim& prim) {
    Attribute nothing;
    nothing.name = "nothing";
    nothing.type = types::Float;
    prim.properties.emplace_back(nothing);
    prim.addAttribute("q", Value::make<types::Quatf>({1, 0, 0, 0}));
    prim.addRelationship("rels", {"/World/Looks", "/World/Candle.points"});
    Relationship unset;
    unset.name = "unset";
    prim.properties.emplace_back(unset);
    prim.addAttribute("s", Value::string("say \"hi\""));
    prim.addAttribute("strings", Value::make<types::StringArray>({"a", "multi\nline \\ \t \x01 \xc3\xa9"}));
    prim.addAttribute("tripled", Value::string("two\nlines"));
    prim.addAttribute("t", Value::token("component"));
    prim.addAttribute("u", Value::make<types::UInt>(4294967295u));
    prim.addAttribute("u64", Value::make<types::UInt64>(UINT64_MAX));
    Dictionary deeper;
    deeper.set("file", Value::asset("./x.usda"));
    Dictionary nested;
    nested.set("deeper", Value::dictionary(deeper));
    Dictionary data;
    data.set("nested", Value::dictionary(nested));
    Attribute& v = prim.addAttribute("v", Value::make<types::Vector3d>({1, 0, 0}));
    v.metadata.set("hidden", Value::make<types::Bool>(true));
    v.metadata.set("displayName", Value::string("Direction"));
    v.metadata.set("customData", Value::dictionary(data));
}

Layer richLayer() {
    Layer layer = layerHeader();
    layer.addRootPrim(world());
    Prim values{.name = "Values", .comment = "a bare comment"};
    addScalars(values);
    addTheRest(values);
    layer.addRootPrim(values);
    Prim schema{.specifier = Specifier::Class, .name = "SchemaLike", .inherits = "/APISchemaBase"};
    schema.addRelationship("none", {});
    layer.addRootPrim(schema);
    Prim over{.specifier = Specifier::Over, .name = "Override"};
    over.references.isExplicit = true;
    over.references.explicitItems = {Reference{.assetPath = "./a.usda"}, Reference{.primPath = "/World"}};
    layer.addRootPrim(over);
    return layer;
}

TEST(UsdaRoundTrip, RichLayerBuiltInCodeWritesTheHandWrittenText) {
    EXPECT_EQ(writeUsda(richLayer()), kCanonical);
}

TEST(UsdaRoundTrip, ReadingTheTextGivesTheModelBuiltInCode) {
    Layer read = readUsda(kCanonical, "rich.usda");
    EXPECT_TRUE(read == richLayer());
}

TEST(UsdaRoundTrip, WriteReadWriteIsByteIdentical) {
    std::string first = writeUsda(readUsda(kCanonical, "rich.usda"));
    std::string second = writeUsda(readUsda(first, "rich.usda"));
    EXPECT_EQ(first, kCanonical);
    EXPECT_EQ(second, first);
}

// The same layer as a person might type it: comments, ';' separators, one-line
// metadata, true/false and 1/0, other number spellings, single quotes, trailing
// commas, CRLF line ends, unsorted metadata.
constexpr std::string_view kMessy =
    "#usda 1.0\r\n"
    "# header comment\r\n"
    "( upAxis = \"Y\"; metersPerUnit = 1e-2  # centimetres\n"
    "  defaultPrim = 'World'\n"
    "  doc = \"A layer that uses\\nevery construct of the subset.\"\n"
    "  \"Opal round-trip test layer\"\n"
    "  customLayerData = { dictionary opal = { int version = 1 }\n"
    "                      string creator = \"opal-test\" }\n"
    "  startTimeCode = 1.0; endTimeCode = 1E1\n"
    "  subLayers = [@./base.usda@, @@@odd@name.usda@@@,]\n"
    ")\n"
    "def Xform \"World\" (kind = \"assembly\") {\n"
    "  double3 xformOp:translate = (0.0, 1.50, -2)\n"
    "  matrix4d xformOp:transform = ((1,0,0,0),(0,1,0,0),(0,0,1,0),(2,3,4,1))\n"
    "  uniform token[] xformOpOrder = [\"xformOp:translate\", 'xformOp:transform',]\n"
    "  def Mesh \"Candle\" (\n"
    "    references = None\n"
    ") {}\n"
    "}\n";

TEST(UsdaRoundTrip, MessyHandWrittenTextReadsToTheCanonicalModel) {
    Layer messy = readUsda(kMessy, "messy.usda");
    Layer canonical = readUsda(kCanonical, "rich.usda");
    EXPECT_EQ(messy.comment, canonical.comment);
    EXPECT_TRUE(messy.metadata == canonical.metadata);
    EXPECT_EQ(messy.subLayers, canonical.subLayers);
    const Prim& world = messy.prim("/World");
    const Prim& expected = canonical.prim("/World");
    EXPECT_TRUE(world.metadata == expected.metadata);
    ASSERT_EQ(world.properties.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(world.properties[i] == expected.properties[i]) << propertyName(world.properties[i]);
    }
    EXPECT_TRUE(messy.prim("/World/Candle").references.isExplicit);
    EXPECT_TRUE(readUsda(writeUsda(messy), "again.usda") == messy);
}

TEST(UsdaRoundTrip, EmptyLayerIsJustTheHeader) {
    EXPECT_EQ(writeUsda(Layer{}), "#usda 1.0\n");
    EXPECT_TRUE(readUsda("#usda 1.0\n", "empty.usda") == Layer{});
    EXPECT_TRUE(readUsda("#usda 1.0", "empty.usda") == Layer{});
}

}  // namespace
}  // namespace opal::usda
