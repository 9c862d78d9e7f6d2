// Discovery, ordering, precedence and load errors of the plugin registry, against the
// real fixture modules (tests/plugin/fixture) and manifests written here.
#include "plugin/plugin_registry.h"

#include "schema/error.h"
#include "tests/plugin/fixture_plugins.h"
#include "tests/plugin/temp_dir.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

namespace fs = std::filesystem;

using test::FixtureDir;
using test::isLoaded;
using test::SupportedModule;

std::vector<std::string> typeNames(const PluginRegistry& registry) {
    std::vector<std::string> names;
    for (const RendererPluginInfo& info : registry.rendererPlugins()) names.push_back(info.typeName);
    return names;
}

// A manifest declaring one renderer type in the supported fixture module.
std::string rendererManifest(const std::string& type, int priority, const std::string& extra = "",
                             const std::string& library = SupportedModule.string()) {
    return R"({"Plugins": [{"Type": "library", "Name": ")" + type + R"(", "LibraryPath": ")" + library +
           R"(", "Info": {"Types": {")" + type + R"(": {"bases": ["HdRendererPlugin"], "displayName": ")" + type +
           R"(", "priority": )" + std::to_string(priority) + extra + "}}}}]}";
}

std::string createError(const PluginRegistry& registry, const std::string& type) {
    try {
        registry.createRendererPlugin(type);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(PluginRegistry, DiscoversTheFixturePluginsThroughTheirGeneratedManifests) {
    PluginRegistry registry({FixtureDir});
    EXPECT_TRUE(registry.problems().empty()) << registry.problems().front();
    // The directory's plugInfo.json includes "*/": one manifest per plugin below it.
    EXPECT_EQ(registry.manifests(), (std::vector<fs::path>{FixtureDir / "plugInfo.json",
                                                            FixtureDir / "opalTestRenderer" / "plugInfo.json",
                                                            FixtureDir / "opalTestUnsupportedRenderer" / "plugInfo.json"}));
    ASSERT_EQ(registry.rendererPlugins().size(), 2u);
    const RendererPluginInfo* info = registry.findRendererPlugin("OpalTestRendererPlugin");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->displayName, "Opal Test Renderer");
    EXPECT_EQ(info->priority, 10);
    EXPECT_EQ(info->pluginName, "opalTestRenderer");
    EXPECT_EQ(info->libraryPath, SupportedModule);
    EXPECT_EQ(info->manifestPath, FixtureDir / "opalTestRenderer" / "plugInfo.json");
    EXPECT_EQ(info->factorySymbol, "OpalTestRendererPlugin_create");
    EXPECT_EQ(registry.findRendererPlugin("OpalTestUnsupportedRendererPlugin")->factorySymbol,
              "opalTestCreateUnsupportedRenderer");
    EXPECT_EQ(registry.findRendererPlugin("Nothing"), nullptr);
}

TEST(PluginRegistry, ASearchPathMayNameTheManifestFileItself) {
    PluginRegistry registry({FixtureDir / "opalTestRenderer" / "plugInfo.json"});
    EXPECT_EQ(typeNames(registry), std::vector<std::string>{"OpalTestRendererPlugin"});
}

TEST(PluginRegistry, DefaultIsTheFirstSupportedPluginInPriorityOrder) {
    PluginRegistry registry({FixtureDir});
    // The unsupported plugin ranks first (priority 0 < 10), so the default skips it.
    EXPECT_EQ(typeNames(registry), (std::vector<std::string>{"OpalTestUnsupportedRendererPlugin", "OpalTestRendererPlugin"}));
    RendererPluginHandle plugin = registry.defaultRendererPlugin();
    EXPECT_EQ(plugin.info().typeName, "OpalTestRendererPlugin");
    EXPECT_EQ(plugin->displayName(), "Opal Test Renderer");
    EXPECT_TRUE(plugin->isSupported());
    EXPECT_FALSE(registry.createRendererPlugin("OpalTestUnsupportedRendererPlugin")->isSupported());
}

TEST(PluginRegistry, ListsBySmallerPriorityFirstThenTypeName) {
    test::TempDir dir;
    dir.write("plugInfo.json", R"({"Includes": ["*/"]})");
    dir.write("b/plugInfo.json", rendererManifest("Beta", 5));
    dir.write("a/plugInfo.json", rendererManifest("Alpha", 5));
    dir.write("c/plugInfo.json", rendererManifest("Gamma", -3));
    dir.write("d/plugInfo.json", rendererManifest("Delta", 99));
    PluginRegistry registry({dir.path()});
    EXPECT_EQ(typeNames(registry), (std::vector<std::string>{"Gamma", "Alpha", "Beta", "Delta"}));
}

TEST(PluginRegistry, OnlyTypesBasedOnHdRendererPluginAreRenderers) {
    test::TempDir dir;
    dir.write("plugInfo.json", R"({"Plugins": [{"Type": "resource", "Name": "opalSchema", "Info": {"Types": {
        "OpalSubsurfaceAPI": {"bases": ["UsdAPISchemaBase"], "schemaKind": "singleApplyAPI"}}}}]})");
    PluginRegistry registry({dir.path()});
    EXPECT_TRUE(registry.rendererPlugins().empty());
    EXPECT_TRUE(registry.problems().empty());
}

TEST(PluginRegistry, FollowsIncludesWithGlobsRecursionAndCycles) {
    test::TempDir dir;
    dir.write("plugInfo.json", R"({"Includes": ["one/", "globbed/*/", "deep/**/", "more.json", "plugInfo.json"]})");
    dir.write("one/plugInfo.json", rendererManifest("One", 1));
    dir.write("globbed/x/plugInfo.json", rendererManifest("X", 2));
    dir.write("globbed/y/plugInfo.json", rendererManifest("Y", 3));
    dir.write("deep/a/b/plugInfo.json", rendererManifest("Deep", 4));
    // more.json includes the top manifest again: each manifest is read once.
    dir.write("more.json", R"({"Includes": ["plugInfo.json", "one/"]})");
    PluginRegistry registry({dir.path()});
    EXPECT_TRUE(registry.problems().empty()) << registry.problems().front();
    EXPECT_EQ(typeNames(registry), (std::vector<std::string>{"One", "X", "Y", "Deep"}));
    EXPECT_EQ(registry.manifests().size(), 6u);
}

TEST(PluginRegistry, ResolvesARelativeLibraryPathAgainstRoot) {
    test::TempDir dir;
    fs::create_directories(dir.path() / "root" / "libs");
    fs::copy_file(SupportedModule, dir.path() / "root" / "libs" / "copy.so");
    // manifests/m/plugInfo.json -> Root ../../root -> LibraryPath libs/copy.so
    dir.write("manifests/m/plugInfo.json", R"({"Plugins": [{"Type": "library", "Name": "copy", "Root": "../../root",
        "LibraryPath": "libs/copy.so", "Info": {"Types": {"OpalTestRendererPlugin": {
        "bases": ["HdRendererPlugin"], "displayName": "Copy", "priority": 1}}}}]})");
    PluginRegistry registry({dir.path() / "manifests" / "m"});
    ASSERT_EQ(registry.rendererPlugins().size(), 1u) << registry.problems().front();
    EXPECT_EQ(registry.rendererPlugins()[0].libraryPath, dir.path() / "root" / "libs" / "copy.so");
    RendererPluginHandle plugin = registry.createRendererPlugin("OpalTestRendererPlugin");
    EXPECT_EQ(plugin->displayName(), "Opal Test Renderer");
}

TEST(PluginRegistry, TheFirstDeclarationOfATypeWinsAndTheOtherIsReported) {
    test::TempDir dir;
    fs::path first = dir.write("first/plugInfo.json", rendererManifest("Twice", 1, "", "/first/lib.so"));
    fs::path second = dir.write("second/plugInfo.json", rendererManifest("Twice", 0, "", "/second/lib.so"));
    PluginRegistry registry({dir.path() / "first", dir.path() / "second"});
    ASSERT_EQ(registry.rendererPlugins().size(), 1u);
    EXPECT_EQ(registry.rendererPlugins()[0].libraryPath, fs::path("/first/lib.so"));
    ASSERT_EQ(registry.problems().size(), 1u);
    EXPECT_EQ(registry.problems()[0], second.string() + ": Plugins[0].Info.Types.Twice: renderer plugin type 'Twice' "
                                                        "is declared already by " + first.string() + "; this declaration is ignored");
}

TEST(PluginRegistry, BadManifestsAreReportedWithTheirFileAndDoNotStopDiscovery) {
    struct Case {
        std::string text;
        std::string expected;  // how the problem starts after "<file>: " (or "<file>:" and line:column)
    };
    const Case cases[] = {
        // nlohmann stops at the end of the offending token: "Name" ends in column 29.
        {"{\n  \"Plugins\": [\n    {\"Type\": \"library\" \"Name\": \"a\"}\n  ]\n}\n",
         "3:29: JSON syntax error: syntax error while parsing object - unexpected string literal"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "Info": {}}]})",
         "Plugins[0]: required key 'LibraryPath' is missing (a \"library\" plugin names its library)"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "priority": 1}}}}]})",
         "Plugins[0].Info.Types.T: renderer plugin type has no 'displayName'"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": "T"}}}}]})",
         "Plugins[0].Info.Types.T: renderer plugin type has no 'priority'"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": 1.5}}}}]})",
         "Plugins[0].Info.Types.T.priority: expected an integer, found number"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": "high"}}}}]})",
         "Plugins[0].Info.Types.T.priority: expected an integer, found string"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": 3000000000}}}}]})",
         "Plugins[0].Info.Types.T.priority: out of range for an int: 3000000000"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": 7, "priority": 1}}}}]})",
         "Plugins[0].Info.Types.T.displayName: expected a non-empty string, found 7"},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": 1, "factory": "not a symbol"}}}}]})",
         "Plugins[0].Info.Types.T.factory: expected a C function name, found \"not a symbol\""},
        {R"({"Plugins": [{"Type": "library", "Name": "a", "LibraryPath": "a.so", "Info": {"Types": {"my::Renderer": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": 1}}}}]})",
         "Plugins[0].Info.Types.my::Renderer: type name is not a C identifier, so it needs a \"factory\" symbol name"},
        {R"({"Plugins": [{"Type": "resource", "Name": "a", "Info": {"Types": {"T": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": 1}}}}]})",
         "Plugins[0].Info.Types.T: a renderer plugin type must come from a \"library\" plugin with a LibraryPath"},
    };
    for (const Case& c : cases) {
        test::TempDir dir;
        fs::path bad = dir.write("bad/plugInfo.json", c.text);
        dir.write("good/plugInfo.json", rendererManifest("Good", 1));
        PluginRegistry registry({dir.path() / "bad", dir.path() / "good"});
        ASSERT_EQ(registry.problems().size(), 1u) << c.text;
        std::string separator = c.expected.front() >= '0' && c.expected.front() <= '9' ? ":" : ": ";
        EXPECT_EQ(registry.problems()[0].rfind(bad.string() + separator + c.expected, 0), 0u) << registry.problems()[0];
        EXPECT_EQ(typeNames(registry), std::vector<std::string>{"Good"}) << c.text;
    }
}

TEST(PluginRegistry, MissingSearchPathsAndManifestsAreReported) {
    test::TempDir dir;
    fs::create_directories(dir.path() / "empty");
    dir.write("top/plugInfo.json", R"({"Includes": ["missing/"]})");
    PluginRegistry registry({dir.path() / "nowhere", dir.path() / "empty", dir.path() / "top"});
    EXPECT_EQ(registry.problems(), (std::vector<std::string>{
                                       (dir.path() / "nowhere").string() + ": plugin search path does not exist",
                                       (dir.path() / "empty" / "plugInfo.json").string() + ": no such plugin manifest",
                                       (dir.path() / "top" / "missing" / "plugInfo.json").string() + ": no such plugin manifest"}));
}

TEST(PluginRegistry, LoadFailuresThrowErrorsNamingTheCause) {
    test::TempDir dir;
    fs::path notALibrary = dir.write("text.so", std::string(4096, '#'));
    dir.write("plugInfo.json", R"({"Plugins": [
        {"Type": "library", "Name": "m", "LibraryPath": "missing.so", "Info": {"Types": {
            "Missing": {"bases": ["HdRendererPlugin"], "displayName": "M", "priority": 1}}}},
        {"Type": "library", "Name": "t", "LibraryPath": "text.so", "Info": {"Types": {
            "Text": {"bases": ["HdRendererPlugin"], "displayName": "T", "priority": 2}}}},
        {"Type": "library", "Name": "f", "LibraryPath": ")" + SupportedModule.string() + R"(", "Info": {"Types": {
            "NoSymbol": {"bases": ["HdRendererPlugin"], "displayName": "S", "priority": 3},
            "NullFactory": {"bases": ["HdRendererPlugin"], "displayName": "N", "priority": 4, "factory": "opalTestNullFactory"},
            "Throwing": {"bases": ["HdRendererPlugin"], "displayName": "X", "priority": 5, "factory": "opalTestThrowingFactory"}}}}]})");
    PluginRegistry registry({dir.path()});
    ASSERT_EQ(registry.rendererPlugins().size(), 5u) << registry.problems().front();
    const std::string manifest = (dir.path() / "plugInfo.json").string();

    EXPECT_EQ(createError(registry, "Missing"), "renderer plugin 'Missing' (" + manifest + "): " +
                                                    (dir.path() / "missing.so").string() + ": plugin library not found");
    std::string text = createError(registry, "Text");
    EXPECT_EQ(text.rfind("renderer plugin 'Text' (" + manifest + "): " + notALibrary.string() + ": cannot load plugin library: ", 0), 0u) << text;
    EXPECT_NE(text.find("invalid ELF header"), std::string::npos) << text;  // dlerror's words
    std::string noSymbol = createError(registry, "NoSymbol");
    EXPECT_EQ(noSymbol.rfind("renderer plugin 'NoSymbol' (" + manifest + "): " + SupportedModule.string() +
                                 ": plugin library has no symbol 'NoSymbol_create': ", 0), 0u) << noSymbol;
    EXPECT_NE(noSymbol.find("undefined symbol: NoSymbol_create"), std::string::npos) << noSymbol;
    EXPECT_EQ(createError(registry, "NullFactory"), "renderer plugin 'NullFactory' (" + manifest + "): factory 'opalTestNullFactory' in " +
                                                        SupportedModule.string() + " returned null");
    EXPECT_EQ(createError(registry, "Throwing"), "renderer plugin 'Throwing' (" + manifest + "): factory 'opalTestThrowingFactory' failed: "
                                                 "opalTestThrowingFactory: this factory always fails");

    // None of them can be the default; the error says why for each.
    try {
        registry.defaultRendererPlugin();
        FAIL() << "no error";
    } catch (const Error& e) {
        std::string message = e.what();
        for (const char* type : {"'Missing'", "'Text'", "'NoSymbol'", "'NullFactory'", "'Throwing'"})
            EXPECT_NE(message.find(type), std::string::npos) << message;
    }
    EXPECT_FALSE(isLoaded(SupportedModule));
}

TEST(PluginRegistry, AnUnknownTypeNamesWhatIsKnownAndWhatWasSkipped) {
    test::TempDir dir;
    fs::path broken = dir.write("broken/plugInfo.json", "{");
    PluginRegistry registry({FixtureDir, dir.path() / "broken"});
    std::string message = createError(registry, "Storm");
    EXPECT_EQ(message.rfind("no renderer plugin 'Storm' (available: Opal Unsupported Test Renderer "
                            "(OpalTestUnsupportedRendererPlugin, priority 0), Opal Test Renderer "
                            "(OpalTestRendererPlugin, priority 10); search paths: " +
                                FixtureDir.string() + ":" + (dir.path() / "broken").string() +
                                 "); problems while reading manifests: " + broken.string() + ":1:2: JSON syntax error", 0),
              0u)
        << message;
}

TEST(PluginRegistry, WithNoPluginsTheDefaultIsAnError) {
    PluginRegistry registry({});
    EXPECT_TRUE(registry.rendererPlugins().empty());
    EXPECT_THROW(registry.defaultRendererPlugin(), Error);
}

}  // namespace
}  // namespace opal
