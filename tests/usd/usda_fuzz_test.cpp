// The reader never crashes, hangs or throws anything but opal::Error, whatever the
// input: every truncation of a valid layer and every single-character substitution
// from a set of syntax-significant characters either parses or fails cleanly.
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

#include <string>

namespace opal::usda {
namespace {

constexpr std::string_view kValid = R"(#usda 1.0
(
    "comment"
    customLayerData = {
        dictionary d = {
            double[] x = [1, 2.5e-3]
        }
    }
    defaultPrim = "World"
    subLayers = [
        @./base.usda@
    ]
)

def Xform "World" (
    prepend apiSchemas = ["OpalSubsurfaceAPI"]
    kind = "component"
    references = @./a.usda@</Asset>
)
{
    matrix4d xformOp:transform = ( (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1) )
    uniform token[] xformOpOrder = ["xformOp:transform"]
    point3f[] points = [(0, 0, 0), (1, -2, 3e10)] (
        interpolation = "vertex"
    )
    string s = """multi
line"""
    asset a = @@@x@y@@@
    rel r = [
        </World/A>,
        </World.points>,
    ]
    float none = None

    class "C" (
        inherits = </Base>
    )
    {
    }
}
)";

// Counts outcomes; fails the test on anything but success or opal::Error.
struct Outcomes {
    int parsed = 0;
    int rejected = 0;

    void run(const std::string& text) {
        try {
            Layer layer = readUsda(text, "fuzz.usda");
            // Whatever parses must also write and read back to the same model.
            ASSERT_TRUE(readUsda(writeUsda(layer), "again.usda") == layer) << text;
            ++parsed;
        } catch (const opal::Error&) {
            ++rejected;
        } catch (const std::exception& e) {
            FAIL() << "non-opal exception " << e.what() << " for:\n" << text;
        }
    }
};

TEST(UsdaFuzz, ValidLayerParses) { EXPECT_NO_THROW(readUsda(kValid, "fuzz.usda")); }

TEST(UsdaFuzz, EveryTruncationParsesOrFailsCleanly) {
    Outcomes outcomes;
    for (std::size_t n = 0; n < kValid.size(); ++n) {
        outcomes.run(std::string(kValid.substr(0, n)));
    }
    EXPECT_GT(outcomes.rejected, static_cast<int>(kValid.size()) * 9 / 10);
}

TEST(UsdaFuzz, EverySubstitutionParsesOrFailsCleanly) {
    constexpr std::string_view kSubstitutes("\"'()[]{}<>@#;,=.:\n\\-0ex \0\xff", 26);
    Outcomes outcomes;
    std::string text(kValid);
    for (std::size_t i = 0; i < text.size(); ++i) {
        char original = text[i];
        for (char c : kSubstitutes) {
            if (c != original) {
                text[i] = c;
                outcomes.run(text);
            }
        }
        text[i] = original;
    }
    EXPECT_GT(outcomes.rejected, 0);
    EXPECT_GT(outcomes.parsed, 0);
}

TEST(UsdaFuzz, PathologicalInputsFailCleanly) {
    std::vector<std::string> inputs = {
        "", "#", "#usda", "#usda 1.0\n(", "#usda 1.0\n((((((((", "#usda 1.0\ndef",
        "#usda 1.0\ndef \"A\" {" + std::string(100000, '{'),
        "#usda 1.0\ndef \"A\" { float3[] p = [" + std::string(100000, '(') + "\n}",
        "#usda 1.0\ndef \"A\" { int[] p = [" + std::string(100000, '[') + "\n}",
        "#usda 1.0\ndef \"A\" { string s = \"" + std::string(100000, '\\') + "\n}",
        "#usda 1.0\n" + std::string(100000, '\n') + "}",
        std::string("#usda 1.0\n\0def", 14),
    };
    Outcomes outcomes;
    for (const std::string& input : inputs) {
        outcomes.run(input);
    }
    EXPECT_EQ(outcomes.parsed, 0);
}

}  // namespace
}  // namespace opal::usda
