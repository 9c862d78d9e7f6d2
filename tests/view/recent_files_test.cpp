// The recent files: newest first, each once, at most ten, kept in $XDG_CONFIG_HOME/opal;
// a list that cannot be read is named in a warning and started again, and the viewer adds
// every file it opens.
#include "examples/opal-view/core/recent_files.h"
#include "tests/view/view_process.h"

#include <cstdlib>

namespace opal::view {
namespace {

TEST(RecentFiles, NewestFirstEachOnceAtMostTenKeptBetweenRuns) {
    const test::SceneDir dir;
    const std::filesystem::path list = dir / "config/opal/recent.json";
    {
        RecentFiles recent(list);
        for (int i = 0; i < 12; ++i) recent.add(dir / ("scene" + std::to_string(i) + ".usda"));
        recent.add(dir / "sub/../scene5.usda");
    }
    const RecentFiles again(list);
    EXPECT_TRUE(again.warning().empty()) << again.warning();
    ASSERT_EQ(again.files().size(), RecentFiles::Limit);
    EXPECT_EQ(again.files()[0], dir / "scene5.usda");
    EXPECT_EQ(again.files()[1], dir / "scene11.usda");
    EXPECT_EQ(again.files()[9], dir / "scene2.usda");  // 0 and 1 went; 5 moved up, not repeated
}

TEST(RecentFiles, AListThatCannotBeReadIsNamedAndStartedAgain) {
    const test::SceneDir dir;
    const std::filesystem::path list = dir.write("config/opal/recent.json", "{\"recent\": [\"a.usda\", 7]}");
    RecentFiles recent(list);
    EXPECT_EQ(recent.warning(), list.string() + ": recent[1] is not a path string; the list of recent files starts empty");
    EXPECT_TRUE(recent.files().empty());
    dir.write("config/opal/recent.json", "{\"recent\": [");
    EXPECT_NE(RecentFiles(list).warning().find(list.string() + ": "), std::string::npos);
    recent.add(dir / "b.usda");
    EXPECT_EQ(RecentFiles(list).files(), std::vector<std::filesystem::path>{dir / "b.usda"});
}

TEST(RecentFiles, LiveInXdgConfigHomeElseInTheHomeFolder) {
    const char* saved = std::getenv("XDG_CONFIG_HOME");
    const std::string keep = saved ? saved : "";
    ::setenv("XDG_CONFIG_HOME", "/tmp/cfg", 1);
    EXPECT_EQ(recentFilesPath(), std::filesystem::path("/tmp/cfg/opal/recent.json"));
    ::unsetenv("XDG_CONFIG_HOME");
    if (const char* home = std::getenv("HOME")) {
        EXPECT_EQ(recentFilesPath(), std::filesystem::path(home) / ".config/opal/recent.json");
    }
    if (saved) ::setenv("XDG_CONFIG_HOME", keep.c_str(), 1);
}

TEST(RecentFiles, TheViewerAddsEveryFileItOpens) {
    const test::SceneDir dir;
    const std::filesystem::path a = dir.writeSphereAsset("a"), b = dir.writeSphereAsset("b");
    dir.write("config/opal/recent.json", "not json");
    const std::filesystem::path script =
        dir.write("open.script", "load " + test::scriptWord(a) + "\nload " + test::scriptWord(b) + "\nquit\n");
    const test::ViewRun run = test::runOpalView(dir, "--size 160x120 --script " + test::shellWord(script));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("opal-view: warning: " + (dir / "config/opal/recent.json").string() + ": "), std::string::npos)
        << run.err;
    EXPECT_EQ(RecentFiles(dir / "config/opal/recent.json").files(), (std::vector<std::filesystem::path>{b, a}));
}

}  // namespace
}  // namespace opal::view
