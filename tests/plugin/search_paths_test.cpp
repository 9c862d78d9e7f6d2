// The helpers hosts use to gather search paths: $OPAL_PLUGINPATH and the directories
// relative to the executable.
#include "plugin/search_paths.h"

#include "tests/plugin/temp_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace opal {
namespace {

namespace fs = std::filesystem;

TEST(SearchPaths, SplitsAColonSeparatedListSkippingEmptyEntries) {
    EXPECT_EQ(splitSearchPath("/a/plugins:relative/dir::/b/plugInfo.json:"),
              (std::vector<fs::path>{"/a/plugins", "relative/dir", "/b/plugInfo.json"}));
    EXPECT_TRUE(splitSearchPath("").empty());
    EXPECT_TRUE(splitSearchPath(":::").empty());
}

TEST(SearchPaths, ReadsTheNamedEnvironmentVariable) {
    const char* variable = "OPAL_PLUGINPATH_SEARCH_PATHS_TEST";
    unsetenv(variable);
    EXPECT_TRUE(searchPathsFromEnvironment(variable).empty());
    setenv(variable, "/x:/y", 1);
    EXPECT_EQ(searchPathsFromEnvironment(variable), (std::vector<fs::path>{"/x", "/y"}));
    unsetenv(variable);
}

TEST(SearchPaths, TheExecutableIsThisTestProgram) {
    fs::path exe = executablePath();
    EXPECT_TRUE(exe.is_absolute());
    EXPECT_EQ(exe.filename(), "opal-test-plugin");
    EXPECT_TRUE(fs::is_regular_file(exe));
}

TEST(SearchPaths, DefaultsAreThePluginDirectoriesThatExistBesideTheExecutable) {
    test::TempDir dir;
    fs::path exe = dir.path() / "bin" / "opal-render";
    EXPECT_TRUE(defaultSearchPaths(exe).empty());
    fs::create_directories(dir.path() / "lib" / "opal" / "plugins");
    // The build tree's layout; the installed one is the same for a lib/ libdir.
    std::vector<fs::path> paths = defaultSearchPaths(exe);
    ASSERT_FALSE(paths.empty());
    EXPECT_EQ(paths.front(), dir.path() / "lib" / "opal" / "plugins");
}

}  // namespace
}  // namespace opal
