// Every unsupported construct and malformed input is rejected with the exact
// file:line:column of the offending token and a message saying what was found and
// what was expected. Positions in this table were counted by hand.
#include "schema/usd/usda_error.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

#include <string>

namespace opal::usda {
namespace {

struct ErrorCase {
    const char* name;
    std::string text;
    std::string message;  // without the "t.usda:" prefix
};

const std::string H = "#usda 1.0\n";
const std::string kNote = " (Opal's USDA subset: see schema/usd/SUBSET.md)";

// A prim "A" whose body is `body` (its lines start on line 4).
std::string inBody(const std::string& body) { return H + "def \"A\"\n{\n" + body + "\n}\n"; }
// A prim "A" whose metadata block holds `metadata` (its lines start on line 3).
std::string inMetadata(const std::string& metadata) { return H + "def \"A\" (\n" + metadata + "\n)\n{\n}\n"; }
const std::string NUL(1, '\0');

std::vector<ErrorCase> errorCases() {
    return {
        {"MissingHeader", "def \"A\" {}\n",
         "1:1: missing '#usda 1.0' header: the first line of a USDA layer must be '#usda 1.0'"},
        {"WrongVersion", "#usda 2.0\n", "1:7: unsupported USDA version '2.0', expected '1.0'"},
        {"JunkOnHeaderLine", "#usda 1.0 junk\n", "1:7: unsupported USDA version '1.0 junk', expected '1.0'"},
        {"VariantSet", inBody("    variantSet \"v\" = {\n    }"), "4:5: unsupported construct 'variantSet'" + kNote},
        {"Payload", inMetadata("    payload = @a.usda@"), "3:5: unsupported construct 'payload'" + kNote},
        {"InheritsOnDef", inMetadata("    inherits = </B>"), "3:5: unsupported construct 'inherits'" + kNote},
        {"Specializes", inMetadata("    specializes = </B>"), "3:5: unsupported construct 'specializes'" + kNote},
        {"Variants", inMetadata("    variants = {\n        string v = \"a\"\n    }"),
         "3:5: unsupported construct 'variants'" + kNote},
        {"PrependInherits", inMetadata("    prepend inherits = </B>"),
         "3:5: unsupported construct 'prepend inherits'" + kNote},
        {"DeleteApiSchemas", inMetadata("    delete apiSchemas = [\"X\"]"),
         "3:5: unsupported construct 'delete apiSchemas'" + kNote},
        {"PrependVariantSets", inMetadata("    prepend variantSets = \"v\""),
         "3:5: unsupported construct 'prepend variantSets'" + kNote},
        {"ExplicitAndPrepend", inMetadata("    apiSchemas = [\"A\"]\n    prepend apiSchemas = [\"B\"]"),
         "4:5: an explicit 'apiSchemas' list cannot be combined with prepend/append apiSchemas"},
        {"ReferenceOffset", inMetadata("    references = @a.usda@ (offset = 1)"),
         "3:27: unsupported construct 'reference layer offset or metadata'" + kNote},
        {"SubLayersOnPrim", inMetadata("    subLayers = [@a.usda@]"), "3:5: unsupported construct 'subLayers'" + kNote},
        {"DuplicateTimeCode", inBody("    float x.timeSamples = {\n        1: 2,\n        1.0: 3,\n    }"),
         "6:9: duplicate time sample 1.0 (first at t.usda:5:9)"},
        {"UniformTimeSamples", inBody("    uniform float x.timeSamples = {\n        1: 2,\n    }"),
         "4:5: 'x' is uniform, so it cannot have timeSamples"},
        {"UniformDeclarationWithSamples",
         inBody("    uniform float x = 1\n    float x.timeSamples = {\n        1: 2,\n    }"),
         "5:5: 'x' is uniform, so it cannot have timeSamples"},
        {"TimeSamplesOfOtherType", inBody("    float x = 1\n    double x.timeSamples = {\n        1: 2,\n    }"),
         "5:5: the timeSamples of 'x' have type double but its declaration has type float"},
        {"TimeSamplesTwice", inBody("    float x.timeSamples = {\n        1: 2,\n    }\n    float x.timeSamples = {\n        2: 2,\n    }"),
         "7:5: duplicate timeSamples of property 'x' (first at 4:5)"},
        {"MetadataOnTimeSamples", inBody("    float x.timeSamples = {\n        1: 2,\n    } (doc = \"d\")"),
         "6:7: metadata belongs on the attribute's declaration, not on its timeSamples"},
        {"EmptyTimeSamples", inBody("    float x.timeSamples = {}"),
         "4:27: timeSamples = {} holds no sample (remove it, or author a default value)"},
        {"TimeSamplesOfRelationship", inBody("    rel x\n    float x.timeSamples = {\n        1: 2,\n    }"),
         "5:5: 'x' is declared as a relationship and as an attribute (other at t.usda:4:5)"},
        {"TimeCodeNotANumber", inBody("    float x.timeSamples = {\n        a: 2,\n    }"),
         "5:9: unexpected 'a', expected a time code (a number) or '}'"},
        {"TimeSamplesOnRel", inBody("    rel r.timeSamples = {\n    }"),
         "4:11: unsupported construct 'timeSamples'" + kNote},
        {"Connection", inBody("    color3f inputs:c.connect = </M.outputs:c>"),
         "4:22: unsupported construct 'connect'" + kNote},
        {"Spline", inBody("    double x.spline = {\n    }"), "4:14: unsupported construct 'spline'" + kNote},
        {"PrependRel", inBody("    prepend rel r = </B>"), "4:5: unsupported construct 'prepend rel'" + kNote},
        {"ReorderNameChildren", inBody("    reorder nameChildren = [\"a\"]"),
         "4:5: unsupported construct 'reorder nameChildren'" + kNote},
        {"VaryingRel", inBody("    varying rel r"), "4:5: unsupported construct 'varying rel'" + kNote},
        {"UnknownType", inBody("    half h = 1"), "4:5: unknown or unsupported attribute type 'half'" + kNote},
        {"DictionaryAttribute", inBody("    dictionary d = {}"),
         "4:5: unknown or unsupported attribute type 'dictionary'" + kNote},
        {"MalformedNumber", inBody("    float f = 1.2.3"), "4:15: malformed number '1.2.3'"},
        {"NumberWithLetters", inBody("    int i = 12abc"), "4:13: malformed number '12abc'"},
        {"Nan", inBody("    float f = nan"), "4:15: non-finite number 'nan' is not accepted" + kNote},
        {"NegativeInfInArray", inBody("    float[] f = [1, -inf]"),
         "4:21: non-finite number '-inf' is not accepted" + kNote},
        {"IntegerExpected", inBody("    int i = 1.5"), "4:13: expected an integer (int), found number '1.5'"},
        {"IntOutOfRange", inBody("    int i = 2147483648"), "4:13: number '2147483648' is out of range for int"},
        {"UIntNegative", inBody("    uint u = -1"), "4:14: number '-1' is out of range for uint"},
        {"FloatOutOfRange", inBody("    float f = 1e39"), "4:15: number '1e39' is out of range for float"},
        {"TupleTooShort", inBody("    float3 p = (1, 2)"), "4:21: unexpected ')', expected ',' (a tuple of 3 values)"},
        {"TupleTooLong", inBody("    float2 p = (1, 2, 3)"), "4:21: unexpected ',', expected ')' to end a tuple of 2 values"},
        {"BadBool", inBody("    bool b = 2"), "4:14: unexpected number '2', expected a bool (0, 1, true or false)"},
        {"StringForAsset", inBody("    asset a = \"x\""), "4:15: unexpected string \"x\", expected an asset path @...@"},
        {"UnquotedToken", inBody("    token t = abc"), "4:15: unexpected 'abc', expected a quoted string"},
        {"MissingValue", inBody("    int x =\n"), "6:1: unexpected '}', expected a number (int)"},
        {"UnterminatedString", inBody("    string s = \"abc\n"),
         "4:16: unterminated string (strings end on the same line)"},
        {"UnterminatedTripleString", H + "def \"A\" (\n    doc = \"\"\"never\nclosed\n",
         "3:11: unterminated triple-quoted string"},
        {"UnterminatedAsset", inBody("    asset a = @a.usda"),
         "4:15: unterminated asset path (asset paths end on the same line)"},
        {"UnterminatedPath", inBody("    rel r = </A"), "4:13: unterminated path (expected '>' on the same line)"},
        {"BadEscape", inBody("    string s = \"a\\qb\""), "4:16: invalid escape sequence '\\q' in string"},
        {"BadCharacter", inBody("    int x = $"), "4:13: unexpected character '$'"},
        {"SlashComment", inBody("    // not a USDA comment"), "4:5: unexpected character '/'"},
        {"BadTargetPath", inBody("    rel r = </a//b>"), "4:13: invalid relationship target path </a//b>"},
        {"VariantInReference", inMetadata("    references = @a.usda@</A{v=x}>"),
         "3:26: invalid reference path </A{v=x}> (expected an absolute prim path such as </Root/Child>)"},
        {"TrailingGarbage", H + "def \"A\"\n{\n}\n}\n",
         "5:1: unexpected '}', expected 'def', 'over' or 'class' to start a prim"},
        {"GarbageAfterLayerMetadata", H + "(\n)\nfoo\n",
         "4:1: unexpected 'foo', expected 'def', 'over' or 'class' to start a prim"},
        {"UnclosedPrimBody", H + "def \"A\"\n{\n    int x = 1\n",
         "5:1: unexpected end of file, expected a property, a child prim or '}'"},
        {"DuplicateRootPrim", H + "def \"A\"\n{\n}\ndef \"A\"\n{\n}\n", "5:1: duplicate root prim 'A' (first at 2:1)"},
        {"DuplicateChildPrim", inBody("    def \"B\" {\n    }\n    over \"B\" {\n    }"),
         "6:5: duplicate prim 'B' (first at 4:5)"},
        {"DuplicateProperty", inBody("    int x = 1\n    uniform int x = 2"),
         "5:5: duplicate property 'x' (first at 4:5)"},
        {"DuplicateAttributeAndRel", inBody("    int x = 1\n    rel x"), "5:5: duplicate property 'x' (first at 4:5)"},
        {"DuplicateMetadata", inMetadata("    kind = \"a\"\n    kind = \"b\""),
         "4:5: duplicate prim metadata 'kind' (first at 3:5)"},
        {"DuplicateDictionaryKey", inMetadata("    customData = {\n        int a = 1\n        int a = 2\n    }"),
         "5:13: duplicate dictionary key 'a'"},
        {"NoneInDictionary", inMetadata("    customData = {\n        double x = None\n    }"),
         "4:20: unexpected 'None', expected a value of type double (None is only accepted as an attribute value)"},
        {"DictionaryArrayType", inMetadata("    customData = {\n        dictionary[] x = []\n    }"),
         "4:9: unexpected 'dictionary[]', expected a dictionary entry type (e.g. string, double, dictionary) or '}'"},
        {"UnknownPrimMetadata", inMetadata("    foo = 1"), "3:5: unknown prim metadata 'foo'" + kNote},
        {"UnknownLayerMetadata", H + "(\n    colorConfig = @a@\n)\n", "3:5: unknown layer metadata 'colorConfig'" + kNote},
        {"AttributeMetadataOnPrimKey", inBody("    int x = 1 (\n        kind = \"a\"\n    )"),
         "5:9: unknown attribute metadata 'kind'" + kNote},
        {"WrongMetadataType", inMetadata("    kind = 3"), "3:12: unexpected number '3', expected a quoted string"},
        {"MissingEquals", inMetadata("    kind \"x\""), "3:10: unexpected string \"x\", expected '=' after metadata key 'kind'"},
        {"MissingMetadataSeparator", H + "def \"A\" (kind = \"a\" doc = \"b\")\n{\n}\n",
         "2:21: unexpected 'doc', expected a newline or ';' after a metadata entry"},
        {"MissingPropertySeparator", inBody("    int x = 1 int y = 2"),
         "4:15: unexpected 'int', expected a newline or ';' after a property"},
        {"PrimNameNotIdentifier", H + "def \"a b\"\n{\n}\n",
         "2:5: prim name 'a b' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)"},
        {"PrimWithoutName", H + "def Xform\n{\n}\n", "3:1: unexpected '{', expected a quoted prim name"},
        // Text: strings, tokens, names and asset paths are well-formed UTF-8 without NUL.
        {"RawNulInString", inBody("    string s = \"a" + NUL + "b\""), "4:18: string contains a NUL byte"},
        {"EscapedNulInString", inBody("    string s = \"ab\\0\""), "4:19: string contains a NUL byte"},
        {"HexNulInToken", inBody("    token t = \"\\x00\""), "4:16: string contains a NUL byte"},
        {"NulOnSecondLineOfDoc", inMetadata("    doc = \"\"\"first\nse" + NUL + "\"\"\""),
         "4:3: string contains a NUL byte"},
        {"EscapedNulOnSecondLineOfDoc", inMetadata("    doc = \"\"\"first\nse\\x00\"\"\""),
         "4:3: string contains a NUL byte"},
        {"LoneByteInString", inBody("    string s = \"ok\xff\""), "4:19: string is not valid UTF-8 (byte \\xff)"},
        {"EscapedLoneByte", inBody("    string s = \"ok\\xe9\""), "4:19: string is not valid UTF-8 (byte \\xe9)"},
        {"OverlongSlash", inBody("    token t = \"\xc0\xaf\""), "4:16: string is not valid UTF-8 (byte \\xc0)"},
        {"Surrogate", inBody("    string s = \"\xed\xa0\x80\""), "4:17: string is not valid UTF-8 (byte \\xed)"},
        {"AboveU10FFFF", inBody("    string s = \"\xf4\x90\x80\x80\""), "4:17: string is not valid UTF-8 (byte \\xf4)"},
        {"TruncatedSequenceInArray", inBody("    token[] t = [\"a\", \"b\xc3\"]"),
         "4:25: string is not valid UTF-8 (byte \\xc3)"},
        {"NulInAssetPath", inBody("    asset a = @a" + NUL + ".usda@"), "4:17: asset path contains a NUL byte"},
        {"LoneByteInTripleAssetPath", inBody("    asset a = @@@x\xfe@@@"),
         "4:19: asset path is not valid UTF-8 (byte \\xfe)"},
        {"LoneByteInReference", inMetadata("    references = @\xe9.usda@"),
         "3:19: asset path is not valid UTF-8 (byte \\xe9)"},
        {"LoneByteInPrimName", H + "def \"A\xff\"\n{\n}\n", "2:7: string is not valid UTF-8 (byte \\xff)"},
        {"LoneByteInLayerComment", H + "(\n    \"c\xff\"\n)\n", "3:7: string is not valid UTF-8 (byte \\xff)"},
        {"NulInDictionaryKey", inMetadata("    customData = {\n        int \"k" + NUL + "\" = 1\n    }"),
         "4:15: string contains a NUL byte"},
        {"NulInIdentifier", inBody("    int x" + NUL + " = 1"), "4:10: unexpected character '\\x00'"},
        {"LoneByteInIdentifier", inBody("    int x\xff = 1"), "4:10: unexpected character '\\xff'"},
        {"ApiSchemasWithoutBrackets", inMetadata("    apiSchemas = \"A\""),
         "3:18: unexpected string \"A\", expected '[' to start a list of quoted names, or None"},
    };
}

std::string errorOf(const std::string& text) {
    try {
        readUsda(text, "t.usda");
    } catch (const UsdaError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(UsdaErrors, EachCaseFailsAtTheExpectedPositionWithTheExpectedMessage) {
    for (const ErrorCase& c : errorCases()) {
        EXPECT_EQ(errorOf(c.text), "t.usda:" + c.message) << c.name;
    }
}

TEST(UsdaErrors, WellFormedUtf8ReadsBackUnchanged) {
    Layer layer = readUsda(inBody("    string s = \"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x95\xaf\\xc3\\xa9\""), "t.usda");
    EXPECT_EQ(layer.prim("/A").attribute("s").get<types::String>(), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x95\xaf\xc3\xa9");
}

TEST(UsdaErrors, WriterRefusesTextTheReaderWouldRefuse) {
    for (const std::string& bad : {"a" + NUL + "b", std::string("lone \xe9 byte")}) {
        Layer layer;
        Prim prim;
        prim.name = std::string(1, 'A');  // not = "A": GCC 12 misreads that assignment's bound (-Wstringop-overflow)
        prim.addAttribute("s", Value::make<types::String>(bad));
        layer.rootPrims.push_back(prim);
        EXPECT_THROW(writeUsda(layer), opal::Error) << bad;
    }
}

TEST(UsdaErrors, ErrorsCarryTheirLocation) {
    try {
        readUsda(inBody("    half h = 1"), "scene.usda");
        FAIL() << "no error";
    } catch (const UsdaError& e) {
        EXPECT_EQ(*e.where().file, "scene.usda");
        EXPECT_EQ(e.where().line, 4);
        EXPECT_EQ(e.where().column, 5);
    }
}

TEST(UsdaErrors, PrimNestingIsBounded) {
    std::string text = H;
    for (int i = 0; i <= kMaxPrimDepth; ++i) {
        text += "def \"P\" {\n";
    }
    std::string expected = "t.usda:" + std::to_string(kMaxPrimDepth + 2) +
                           ":1: prims nested deeper than " + std::to_string(kMaxPrimDepth) + " levels";
    EXPECT_EQ(errorOf(text), expected);
}

TEST(UsdaErrors, DictionaryNestingIsBoundedWithoutExhaustingTheStack) {
    std::string text = H + "def \"A\" (\n    customData = ";
    for (int i = 0; i < 100000; ++i) {
        text += "{ dictionary d = ";
    }
    std::string error = errorOf(text);
    EXPECT_NE(error.find("dictionaries nested deeper than 32 levels"), std::string::npos) << error;
}

TEST(UsdaErrors, MissingFileNamesThePath) {
    try {
        readUsdaFile("/nonexistent/opal/scene.usda");
        FAIL() << "no error";
    } catch (const opal::Error& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with("/nonexistent/opal/scene.usda: cannot read USDA layer"))
            << e.what();
    }
}

}  // namespace
}  // namespace opal::usda
