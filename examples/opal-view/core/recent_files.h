// The files opal-view opened lately, newest first (File > Open recent), kept between runs
// in $XDG_CONFIG_HOME/opal/recent.json, else ~/.config/opal/recent.json:
//   {"recent": ["/abs/scene.usda", ...]}
// A list that cannot be read does not keep the viewer from starting: it is replaced, and
// the warning names the file and the place (or the system's reason).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opal::view {

// Where the list lives; nothing when neither XDG_CONFIG_HOME nor HOME is set.
std::optional<std::filesystem::path> recentFilesPath();

class RecentFiles {
public:
    static constexpr std::size_t Limit = 10;

    // Reads `file` if it exists; a problem becomes warning() and an empty list.
    explicit RecentFiles(std::optional<std::filesystem::path> file);

    const std::vector<std::filesystem::path>& files() const { return files_; }
    const std::string& warning() const { return warning_; }

    // `opened` (made absolute) goes first, once; the oldest beyond Limit go. Then the list
    // is written atomically (its folder made). Throws opal::Error naming the file.
    void add(const std::filesystem::path& opened);

private:
    std::optional<std::filesystem::path> file_;
    std::vector<std::filesystem::path> files_;
    std::string warning_;
};

}  // namespace opal::view
