// The USD plugin (plugin/usd/plugInfo.json + schema/usd/generatedSchema.usda) registers
// Opal's codeless schemas the way USD 24.08 accepts them. OpenUSD is not a Debian package,
// so these tests check the rules USD applies, taken from OpenUSD v24.08:
//  - usdGenSchema.py (_ExtractNames, ClassInfo, GeneratePlugInfo): the type key is
//    libraryPrefix + className, className defaulting to the class name with its first
//    letter upper-cased; the alias {"UsdSchemaBase": name} is the class name files use;
//    "bases" is the parent's C++ name; "schemaKind" is singleApplyAPI / multipleApplyAPI /
//    nonAppliedAPI from customData apiSchemaType (default singleApply) for API schemas,
//    concreteTyped / abstractTyped for typed ones; applied API schemas inherit
//    APISchemaBase directly; API names end in "API", typed names do not; usdGenSchema
//    writes no other keys than the ones below (no "apiSchemaType" in plugInfo.json), a
//    header of three '#' comment lines, and "Type": "resource" when skipCodeGeneration.
//  - TfType (registering the aliases): "There already is a type named X ...; cannot create
//    an alias of the same name": no alias may equal a type key.
//  - Plug (pxr/base/plug/info.cpp): '#' lines are comments; LibraryPath is required only for
//    "library" plugins; Root and ResourcePath are relative to the plugInfo.json folder. The
//    baselines (testUsdGenSchema/baseline/codeless/plugInfo.json) carry @PLUG_INFO_ROOT@-style
//    placeholders that USD's CMake substitutes; a deployed codeless plugin has them
//    resolved to "." (this folder) and no LibraryPath.
//  - usdGenSchema's generatedSchema.usda holds exactly the classes plugInfo.json registers.
#include "tests/usd/schema_files.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace opal::usda {
namespace {

const nlohmann::json& plugin() {
    static const nlohmann::json info = plugInfo(kSource / "plugin/usd/plugInfo.json");
    return info.at("Plugins").at(0);
}

const nlohmann::json& registeredTypes() { return plugin().at("Info").at("Types"); }

std::string libraryPrefix() { return customString(schema().prim("/GLOBAL"), "libraryPrefix"); }

// usdGenSchema's _ExtractNames: className defaults to _ProperCase(prim name).
std::string typeKey(const Prim& cls) {
    std::string className = customString(cls, "className");
    if (className.empty()) {
        className = cls.name;
        className[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(className[0])));
    }
    return libraryPrefix() + className;
}

// The C++ names of the USD classes Opal's schemas may inherit (their plugInfo.json keys).
std::string usdBaseName(const std::string& inherits) {
    static const std::map<std::string, std::string> kUsd = {
        {"/APISchemaBase", "UsdAPISchemaBase"},
        {"/Typed", "UsdTyped"},
        {"/NonboundableLightBase", "UsdLuxNonboundableLightBase"},
        {"/BoundableLightBase", "UsdLuxBoundableLightBase"},
    };
    auto it = kUsd.find(inherits);
    if (it != kUsd.end()) {
        return it->second;
    }
    const Prim* own = schema().findPrim(inherits);
    return own ? typeKey(*own) : "unknown base " + inherits;
}

bool isApi(const Prim& cls) { return cls.typeName.empty() && cls.inherits == "/APISchemaBase"; }

std::string expectedSchemaKind(const Prim& cls) {
    if (isApi(cls)) {
        std::string type = customString(cls, "apiSchemaType");
        if (type.empty() || type == "singleApply") {
            return "singleApplyAPI";
        }
        if (type == "multipleApply") {
            return "multipleApplyAPI";
        }
        return type == "nonApplied" ? "nonAppliedAPI" : "invalid apiSchemaType " + type;
    }
    return cls.typeName.empty() ? "abstractTyped" : "concreteTyped";
}

TEST(UsdRegistration, EveryTypeKeyDiffersFromEveryAlias) {
    std::set<std::string> keys;
    for (const auto& [key, type] : registeredTypes().items()) {
        keys.insert(key);
    }
    for (const auto& [key, type] : registeredTypes().items()) {
        std::string alias = type.at("alias").at("UsdSchemaBase");
        EXPECT_NE(alias, key);
        EXPECT_FALSE(keys.contains(alias)) << "alias " << alias << " is also a type key";
    }
}

TEST(UsdRegistration, KeysAreLibraryPrefixPlusClassNameAndAliasesAreTheNamesFilesUse) {
    EXPECT_EQ(registeredTypes().size(), schemaClasses().size());
    for (const Prim* cls : schemaClasses()) {
        std::string key = typeKey(*cls);
        ASSERT_TRUE(registeredTypes().contains(key)) << key;
        EXPECT_EQ(registeredTypes()[key].at("alias"), nlohmann::json({{"UsdSchemaBase", cls->name}})) << key;
    }
    // The names Opal's assets and scenes author.
    EXPECT_EQ(registeredTypes().at("OpalSchemaOpalSubsurfaceAPI").at("alias").at("UsdSchemaBase"), "OpalSubsurfaceAPI");
    EXPECT_EQ(registeredTypes().at("OpalSchemaOpalShadowFieldLight").at("alias").at("UsdSchemaBase"),
              "OpalShadowFieldLight");
}

TEST(UsdRegistration, SchemaKindBasesAndNamingFollowUsdGenSchema) {
    const std::set<std::string> kWritten = {"alias", "autoGenerated", "bases", "schemaKind", "apiSchemaAutoApplyTo",
                                            "apiSchemaCanOnlyApplyTo", "apiSchemaAllowedInstanceNames",
                                            "apiSchemaInstances"};
    for (const Prim* cls : schemaClasses()) {
        const nlohmann::json& type = registeredTypes().at(typeKey(*cls));
        EXPECT_EQ(type.at("schemaKind"), expectedSchemaKind(*cls)) << cls->name;
        EXPECT_EQ(type.at("autoGenerated"), true) << cls->name;
        ASSERT_TRUE(cls->inherits) << cls->name;
        EXPECT_EQ(type.at("bases"), nlohmann::json::array({usdBaseName(*cls->inherits)})) << cls->name;
        EXPECT_EQ(cls->name.ends_with("API"), isApi(*cls)) << cls->name;
        if (isApi(*cls)) {
            EXPECT_EQ(type.at("bases"), nlohmann::json::array({"UsdAPISchemaBase"})) << cls->name;
        } else {
            EXPECT_TRUE(customString(*cls, "apiSchemaType").empty()) << cls->name;
        }
        for (const auto& [key, value] : type.items()) {
            EXPECT_TRUE(kWritten.contains(key)) << cls->name << " has key " << key << ", which usdGenSchema never writes";
        }
    }
}

TEST(UsdRegistration, PluginIsACodelessResourceInItsOwnFolder) {
    nlohmann::json info = plugInfo(kSource / "plugin/usd/plugInfo.json");
    ASSERT_EQ(info.at("Plugins").size(), 1u);
    EXPECT_EQ(plugin().at("Name"), customString(schema().prim("/GLOBAL"), "libraryName"));
    EXPECT_TRUE(schema().prim("/GLOBAL").customData()->find("skipCodeGeneration")->get<types::Bool>("skipCodeGeneration"));
    EXPECT_EQ(plugin().at("Type"), "resource");
    EXPECT_EQ(plugin().at("Root"), ".");
    EXPECT_EQ(plugin().at("ResourcePath"), ".");
    EXPECT_FALSE(plugin().contains("LibraryPath"));
    std::set<std::string> keys;
    for (const auto& [key, value] : plugin().items()) {
        keys.insert(key);
    }
    EXPECT_EQ(keys, (std::set<std::string>{"Info", "Name", "ResourcePath", "Root", "Type"}));
    std::string text = fileText(kSource / "plugin/usd/plugInfo.json");
    EXPECT_EQ(text.find("@PLUG_INFO_"), std::string::npos);
    EXPECT_TRUE(text.starts_with("# Portions of this file auto-generated by usdGenSchema.\n"
                                 "# Edits will survive regeneration except for comments and\n"
                                 "# changes to types with autoGenerated=true.\n{\n"));
}

TEST(UsdRegistration, GeneratedSchemaHoldsExactlyTheRegisteredClasses) {
    std::set<std::string> registered;
    for (const auto& [key, type] : registeredTypes().items()) {
        registered.insert(type.at("alias").at("UsdSchemaBase").get<std::string>());
    }
    std::set<std::string> generatedClasses;
    for (const Prim* cls : classesOf(generated())) {
        generatedClasses.insert(cls->name);
        const Prim& source = schema().prim("/" + cls->name);
        EXPECT_EQ(cls->typeName, source.typeName) << cls->name;
    }
    EXPECT_EQ(generatedClasses, registered);
    EXPECT_EQ(generated().rootPrims.size(), generatedClasses.size()) << "generatedSchema.usda holds only classes";
}

// The parser follows USD's rule: a '#' after leading blanks starts a comment line, a '#'
// inside a value does not.
TEST(UsdRegistration, PlugInfoCommentLinesAreStrippedAsUsdDoes) {
    std::filesystem::path file = std::filesystem::temp_directory_path() / "opal-usd-registration-plugInfo.json";
    std::ofstream(file) << "# comment\n  \t# indented comment\n{\"a\": \"#b\"}\n";
    EXPECT_EQ(plugInfo(file), nlohmann::json({{"a", "#b"}}));
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace opal::usda
