// A fresh temporary folder that every user may enter (mode 0755; removed with its
// contents), for tests whose child drops to the user nobody, and what such a test
// observes: a file's contents, a folder's listing, the outcome of a failed rewrite.
#pragma once

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace opal::test {

class OpenTempDir {
public:
    OpenTempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "opal-open-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
        ::chmod(path_.c_str(), 0755);
    }
    ~OpenTempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    OpenTempDir(const OpenTempDir&) = delete;
    OpenTempDir& operator=(const OpenTempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

inline std::string fileContents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The names in `folder`, sorted, separated by spaces.
inline std::string folderListing(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : " ") + n;
    return out;
}

// What a test of a failed rewrite observes (in a child, so carried as text): the error
// message, the previous file's contents afterwards, and the folder's listing.
struct FailedRewrite {
    std::string message, previous, files;
};

inline std::string describeFailedRewrite(const std::string& message, const std::filesystem::path& target) {
    return message + "\n" + fileContents(target) + "\n" + folderListing(target.parent_path());
}

inline FailedRewrite parseFailedRewrite(const std::string& text) {
    FailedRewrite f;
    std::istringstream in(text);
    std::getline(in, f.message);
    std::getline(in, f.previous);
    std::getline(in, f.files);
    return f;
}

}  // namespace opal::test
