// The shipped schema files, read once per test executable: opal.usda (the schema.usda
// usdGenSchema reads), generatedSchema.usda (what it writes) and plugInfo.json.
#pragma once

#include "schema/usd/usda_reader.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opal::usda {

inline const std::filesystem::path kSource = OPAL_SOURCE_DIR;

inline std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline const Layer& schema() {
    static const Layer layer = readUsdaFile(kSource / "schema/usd/opal.usda");
    return layer;
}

inline const Layer& generated() {
    static const Layer layer = readUsdaFile(kSource / "schema/usd/generatedSchema.usda");
    return layer;
}

// plugInfo.json allows comment lines, which JSON does not. USD's Plug (pxr/base/plug/info.cpp)
// blanks a line when its first character other than blank or tab is '#'.
inline nlohmann::json plugInfo(const std::filesystem::path& path) {
    std::stringstream json;
    std::istringstream lines(fileText(path));
    for (std::string line; std::getline(lines, line);) {
        bool comment = line.find('#') < line.find_first_not_of(" \t#");
        json << (comment ? "" : line) << '\n';
    }
    return nlohmann::json::parse(json.str());
}

inline std::vector<const Prim*> classesOf(const Layer& layer) {
    std::vector<const Prim*> classes;
    for (const Prim& prim : layer.rootPrims) {
        if (prim.specifier == Specifier::Class) {
            classes.push_back(&prim);
        }
    }
    return classes;
}

inline std::vector<const Prim*> schemaClasses() { return classesOf(schema()); }

// A customData string or token; empty when not authored.
inline std::string customString(const Prim& prim, std::string_view key) {
    const Value* v = prim.customData() ? prim.customData()->find(key) : nullptr;
    if (!v) {
        return {};
    }
    return v->type() == types::Token ? v->get<types::Token>(key) : v->get<types::String>(key);
}

}  // namespace opal::usda
