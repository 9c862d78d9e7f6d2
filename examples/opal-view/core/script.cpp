#include "examples/opal-view/core/script.h"

#include "examples/opal-view/core/script_words.h"
#include "schema/error.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace opal::view {
namespace {

// One form of an action. Tokens: a literal keyword, "=word" a keyword kept in `words`
// (a parameter name), "W" any word, "N" a finite number.
struct ActionForm {
    const char* pattern;
    ActionKind kind;
};

constexpr ActionForm Forms[] = {
    {"load W", ActionKind::Load},
    {"material set =sigma_s N N N", ActionKind::MaterialSet},
    {"material set =sigma_a N N N", ActionKind::MaterialSet},
    {"material set =eta N", ActionKind::MaterialSet},
    {"material set =roughness N", ActionKind::MaterialSet},
    {"material set =albedo N N N", ActionKind::MaterialSet},
    {"material set =mfp N N N", ActionKind::MaterialSet},
    {"material reset", ActionKind::MaterialReset},
    {"material preset W", ActionKind::MaterialPreset},
    {"light move W N N N", ActionKind::LightMove},
    {"light turn W N N", ActionKind::LightTurn},
    {"light set W =intensity N", ActionKind::LightSet},
    {"light set W =exposure N", ActionKind::LightSet},
    {"light set W =color N N N", ActionKind::LightSet},
    {"light set W =temperature N", ActionKind::LightSet},
    {"light set W =temperature =off", ActionKind::LightSet},
    {"light set W =radius N", ActionKind::LightSet},
    {"light set W =cone N", ActionKind::LightSet},
    {"light set W =softness N", ActionKind::LightSet},
    {"light set W =angle N", ActionKind::LightSet},
    {"light set W =flicker N N N", ActionKind::LightSet},
    {"light add =point", ActionKind::LightAdd},
    {"light add =sphere", ActionKind::LightAdd},
    {"light add =spot", ActionKind::LightAdd},
    {"light add =distant", ActionKind::LightAdd},
    {"light add =dome", ActionKind::LightAdd},
    {"light add =point W", ActionKind::LightAdd},
    {"light add =sphere W", ActionKind::LightAdd},
    {"light add =spot W", ActionKind::LightAdd},
    {"light add =distant W", ActionKind::LightAdd},
    {"light add =dome W", ActionKind::LightAdd},
    {"light add =shadowfield W", ActionKind::LightAdd},
    {"light add =shadowfield W W", ActionKind::LightAdd},
    {"light remove W", ActionKind::LightRemove},
    {"light rename W W", ActionKind::LightRename},
    {"light =enable W", ActionKind::LightEnable},
    {"light =disable W", ActionKind::LightEnable},
    {"environment =rotate N", ActionKind::Environment},
    {"environment =texture W", ActionKind::Environment},
    {"environment =background =on", ActionKind::Environment},
    {"environment =background =off", ActionKind::Environment},
    {"undo", ActionKind::Undo},
    {"redo", ActionKind::Redo},
    {"setting W W", ActionKind::Setting},
    {"panel W =on", ActionKind::Panel},
    {"panel W =off", ActionKind::Panel},
    {"gizmos =on", ActionKind::Gizmos},
    {"gizmos =off", ActionKind::Gizmos},
    {"view W W", ActionKind::View},
    {"exposure N", ActionKind::Exposure},
    {"aov W", ActionKind::Aov},
    {"delegate W", ActionKind::Delegate},
    {"delegates", ActionKind::Delegates},
    {"gamma N", ActionKind::Gamma},
    {"camera frame", ActionKind::CameraFrame},
    {"camera reset", ActionKind::CameraReset},
    {"camera orbit N N", ActionKind::CameraOrbit},
    {"camera focal N", ActionKind::CameraFocal},
    {"camera frame =selection", ActionKind::CameraFrame},
    {"camera use W", ActionKind::CameraUse},
    {"camera fov N", ActionKind::CameraFov},
    {"camera clip N N", ActionKind::CameraClip},
    {"camera clip =auto", ActionKind::CameraClip},
    {"select W", ActionKind::Select},
    {"wipe =on", ActionKind::Wipe},
    {"wipe =off", ActionKind::Wipe},
    {"wipe N", ActionKind::Wipe},
    {"time N", ActionKind::Time},
    {"=play", ActionKind::Play},
    {"=pause", ActionKind::Play},
    {"wait", ActionKind::Wait},
    {"wait N", ActionKind::Wait},
    {"drag =material N", ActionKind::Drag},
    {"drag =light W N", ActionKind::Drag},
    {"screenshot W", ActionKind::Screenshot},
    {"save exr W", ActionKind::SaveExr},
    {"save png W", ActionKind::SavePng},
    {"save usda W", ActionKind::SaveUsda},
    {"probe N N", ActionKind::Probe},
    {"quit", ActionKind::Quit},
};

std::vector<std::string> tokensOf(const char* pattern) {
    std::vector<std::string> tokens;
    std::istringstream in(pattern);
    for (std::string token; in >> token;) tokens.push_back(token);
    return tokens;
}

bool parseNumber(const std::string& word, double& value) {
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(word.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

// The action `words` spell in this form, or false.
bool match(const ActionForm& form, const std::vector<std::string>& words, ScriptAction& action) {
    const std::vector<std::string> tokens = tokensOf(form.pattern);
    if (tokens.size() != words.size()) return false;
    ScriptAction candidate{form.kind, action.where, {}, {}};
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const std::string& token = tokens[i];
        if (token == "W") {
            candidate.words.push_back(words[i]);
        } else if (token == "N") {
            double value = 0.0;
            if (!parseNumber(words[i], value)) return false;
            candidate.numbers.push_back(value);
        } else if (token.front() == '=') {
            if (words[i] != token.substr(1)) return false;
            candidate.words.push_back(words[i]);
        } else if (words[i] != token) {
            return false;
        }
    }
    action = std::move(candidate);
    return true;
}

std::string readable(const char* pattern) {
    std::string text;
    for (std::string token : tokensOf(pattern)) {
        if (token == "W") token = "WORD";
        else if (token == "N") token = "NUMBER";
        else if (token.front() == '=') token = token.substr(1);
        text += (text.empty() ? "" : " ") + token;
    }
    return text;
}

std::string usage(const std::string& verb) {
    std::string forms, verbs;
    for (const ActionForm& form : Forms) {
        std::string first = tokensOf(form.pattern).front();
        if (first.front() == '=') first.erase(0, 1);  // play, pause
        if (first == verb) forms += (forms.empty() ? "" : "; ") + readable(form.pattern);
        if (verbs.find(" " + first + ",") == std::string::npos) verbs += " " + first + ",";
    }
    if (forms.empty()) return "unknown action '" + verb + "' (actions:" + verbs.substr(0, verbs.size() - 1) + ")";
    return "bad arguments for '" + verb + "': expected " + forms;
}

ScriptAction parseLine(const std::vector<std::string>& words, const std::string& where) {
    ScriptAction action{ActionKind::Quit, where, {}, {}};
    for (const ActionForm& form : Forms)
        if (match(form, words, action)) return action;
    throw Error(where + ": " + usage(words.front()));
}

}  // namespace

std::vector<ScriptAction> parseScript(const std::string& text, const std::string& fileName) {
    std::vector<ScriptAction> actions;
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        const std::string where = fileName + ":" + std::to_string(++number);
        std::vector<std::string> words;
        try {
            words = splitScriptWords(line);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        if (!words.empty()) actions.push_back(parseLine(words, where));
    }
    return actions;
}

std::vector<ScriptAction> readScript(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot read the script");
    std::stringstream text;
    text << in.rdbuf();
    return parseScript(text.str(), file.string());
}

}  // namespace opal::view
