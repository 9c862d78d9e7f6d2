// The script language of opal-view --script: every documented form parses into its action,
// and anything else fails naming FILE:LINE before a single action runs.
#include "examples/opal-view/core/script.h"
#include "schema/error.h"

#include <gtest/gtest.h>

namespace opal::view {
namespace {

std::string errorOf(const std::string& text) {
    try {
        parseScript(text, "look.script");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Script, ParsesEveryActionWithItsArguments) {
    const std::vector<ScriptAction> actions = parseScript(R"(# a comment line

load "my scene.usda"
material set sigma_a 0.3 0.1 0.3   # trailing comment
material set eta 1.4
material reset
light move /World/Key -30 0 15.5
light set /World/Key color 1 0.5 0.25
view "sRGB - Display" "ACES 1.0 - SDR Video"
exposure -1.5
aov subsurface
camera orbit 10 -5
wait 20
drag light /World/Key 5
screenshot out.png
save exr out.exr
quit
)", "look.script");
    ASSERT_EQ(actions.size(), 15u);
    EXPECT_EQ(actions[0].kind, ActionKind::Load);
    EXPECT_EQ(actions[0].words, std::vector<std::string>{"my scene.usda"});
    EXPECT_EQ(actions[0].where, "look.script:3");
    EXPECT_EQ(actions[1].kind, ActionKind::MaterialSet);
    EXPECT_EQ(actions[1].words, std::vector<std::string>{"sigma_a"});
    EXPECT_EQ(actions[1].numbers, (std::vector<double>{0.3, 0.1, 0.3}));
    EXPECT_EQ(actions[3].kind, ActionKind::MaterialReset);
    EXPECT_EQ(actions[4].kind, ActionKind::LightMove);
    EXPECT_EQ(actions[4].numbers, (std::vector<double>{-30.0, 0.0, 15.5}));
    EXPECT_EQ(actions[5].words, (std::vector<std::string>{"/World/Key", "color"}));
    EXPECT_EQ(actions[6].words, (std::vector<std::string>{"sRGB - Display", "ACES 1.0 - SDR Video"}));
    EXPECT_EQ(actions[7].numbers, std::vector<double>{-1.5});
    EXPECT_EQ(actions[9].kind, ActionKind::CameraOrbit);
    EXPECT_EQ(actions[10].numbers, std::vector<double>{20.0});
    EXPECT_EQ(actions[11].kind, ActionKind::Drag);
    EXPECT_EQ(actions[11].words, (std::vector<std::string>{"light", "/World/Key"}));
    EXPECT_EQ(actions[11].numbers, std::vector<double>{5.0});
    EXPECT_EQ(actions[13].kind, ActionKind::SaveExr);
    EXPECT_EQ(actions[13].where, "look.script:16");
    EXPECT_EQ(actions[14].kind, ActionKind::Quit);
}

TEST(Script, AnUnknownActionFailsWithItsLineAndTheActions) {
    const std::string error = errorOf("load a.usda\n\nfly away\n");
    EXPECT_EQ(error.rfind("look.script:3: unknown action 'fly'", 0), 0u) << error;
    EXPECT_NE(error.find("load"), std::string::npos) << error;
}

TEST(Script, WrongArgumentsFailWithTheFormsOfThatAction) {
    const std::string count = errorOf("material set sigma_a 1 2\n");
    EXPECT_EQ(count.rfind("look.script:1: bad arguments for 'material'", 0), 0u) << count;
    EXPECT_NE(count.find("material set sigma_a NUMBER NUMBER NUMBER"), std::string::npos) << count;
    EXPECT_EQ(errorOf("quit\nexposure bright\n").rfind("look.script:2: bad arguments for 'exposure'", 0), 0u);
    EXPECT_EQ(errorOf("material set sigma_q 1 2 3\n").rfind("look.script:1: ", 0), 0u);
    EXPECT_EQ(errorOf("exposure nan\n").rfind("look.script:1: ", 0), 0u);  // numbers are finite
    EXPECT_EQ(errorOf("quit now\n").rfind("look.script:1: ", 0), 0u);
}

TEST(Script, AnUnclosedQuoteFailsWithItsLine) {
    EXPECT_EQ(errorOf("quit\nload \"a.usda\n"), "look.script:2: unclosed double quote");
}

TEST(Script, AnUnreadableFileIsNamed) {
    try {
        readScript("/nonexistent/look.script");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/look.script: cannot read the script");
    }
}

}  // namespace
}  // namespace opal::view

namespace opal::view {
namespace {

TEST(Script, ParsesTheLightHistorySettingSaveAndProbeActions) {
    const std::vector<ScriptAction> actions = parseScript(R"(material preset marble
light add point
light add dome /World/Sky
light remove /World/Sky
light rename /World/Key Rim
light disable /World/Key
light enable /World/Key
undo
redo
setting opal:reference true
save png out.png
save usda "my scene.usda"
probe 12 34
)", "look.script");
    ASSERT_EQ(actions.size(), 13u);
    EXPECT_EQ(actions[0].kind, ActionKind::MaterialPreset);
    EXPECT_EQ(actions[0].words, std::vector<std::string>{"marble"});
    EXPECT_EQ(actions[1].kind, ActionKind::LightAdd);
    EXPECT_EQ(actions[1].words, std::vector<std::string>{"point"});
    EXPECT_EQ(actions[2].words, (std::vector<std::string>{"dome", "/World/Sky"}));
    EXPECT_EQ(actions[3].kind, ActionKind::LightRemove);
    EXPECT_EQ(actions[4].kind, ActionKind::LightRename);
    EXPECT_EQ(actions[4].words, (std::vector<std::string>{"/World/Key", "Rim"}));
    EXPECT_EQ(actions[5].kind, ActionKind::LightEnable);
    EXPECT_EQ(actions[5].words, (std::vector<std::string>{"disable", "/World/Key"}));
    EXPECT_EQ(actions[6].words, (std::vector<std::string>{"enable", "/World/Key"}));
    EXPECT_EQ(actions[7].kind, ActionKind::Undo);
    EXPECT_EQ(actions[8].kind, ActionKind::Redo);
    EXPECT_EQ(actions[9].kind, ActionKind::Setting);
    EXPECT_EQ(actions[9].words, (std::vector<std::string>{"opal:reference", "true"}));
    EXPECT_EQ(actions[10].kind, ActionKind::SavePng);
    EXPECT_EQ(actions[11].kind, ActionKind::SaveUsda);
    EXPECT_EQ(actions[11].words, std::vector<std::string>{"my scene.usda"});
    EXPECT_EQ(actions[12].kind, ActionKind::Probe);
    EXPECT_EQ(actions[12].numbers, (std::vector<double>{12.0, 34.0}));
    EXPECT_EQ(errorOf("light add area\n").rfind("look.script:1: bad arguments for 'light'", 0), 0u);
    EXPECT_EQ(errorOf("save tiff out.tif\n").rfind("look.script:1: bad arguments for 'save'", 0), 0u);
}

}  // namespace
}  // namespace opal::view

namespace opal::view {
namespace {

// Every light type is added, and each type's own parameters are set by name.
TEST(Script, ParsesEveryLightTypeAndTheTypeSpecificParameters) {
    const std::vector<ScriptAction> actions = parseScript(R"(light add sphere
light add spot /World/Spot
light set /World/Spot radius 0.5
light set /World/Spot cone 25
light set /World/Spot softness 0.3
light set /World/Sun angle 2.5
)", "look.script");
    ASSERT_EQ(actions.size(), 6u);
    EXPECT_EQ(actions[0].kind, ActionKind::LightAdd);
    EXPECT_EQ(actions[0].words, std::vector<std::string>{"sphere"});
    EXPECT_EQ(actions[1].words, (std::vector<std::string>{"spot", "/World/Spot"}));
    const char* parameters[] = {"radius", "cone", "softness", "angle"};
    const double values[] = {0.5, 25.0, 0.3, 2.5};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(actions[2 + i].kind, ActionKind::LightSet);
        EXPECT_EQ(actions[2 + i].words.at(1), parameters[i]);
        EXPECT_EQ(actions[2 + i].numbers, std::vector<double>{values[i]});
    }
    EXPECT_EQ(errorOf("light set /World/Spot cone wide\n").rfind("look.script:1: bad arguments for 'light'", 0), 0u);
    EXPECT_EQ(errorOf("light set /World/Spot width 3\n").rfind("look.script:1: bad arguments for 'light'", 0), 0u);
}

TEST(Script, ParsesTheDistantLightTurnAndTheGizmoSwitch) {
    const std::vector<ScriptAction> actions = parseScript("light turn /World/Sun 120 -40\ngizmos off\ngizmos on\n", "look.script");
    ASSERT_EQ(actions.size(), 3u);
    EXPECT_EQ(actions[0].kind, ActionKind::LightTurn);
    EXPECT_EQ(actions[0].words, std::vector<std::string>{"/World/Sun"});
    EXPECT_EQ(actions[0].numbers, (std::vector<double>{120.0, -40.0}));
    EXPECT_EQ(actions[1].kind, ActionKind::Gizmos);
    EXPECT_EQ(actions[1].words, std::vector<std::string>{"off"});
    EXPECT_EQ(actions[2].words, std::vector<std::string>{"on"});
    EXPECT_EQ(errorOf("gizmos maybe\n").rfind("look.script:1: bad arguments for 'gizmos'", 0), 0u);
    EXPECT_EQ(errorOf("light turn /World/Sun 10\n").rfind("look.script:1: bad arguments for 'light'", 0), 0u);
}

}  // namespace
}  // namespace opal::view
