#include "examples/opal-view/core/recent_files.h"

#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace opal::view {
namespace {

std::vector<std::filesystem::path> readList(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read it");
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json json = nlohmann::json::parse(text.str());  // parse_error names the byte
    if (!json.is_object() || !json.contains("recent") || !json["recent"].is_array())
        throw Error("expected {\"recent\": [paths]}");
    std::vector<std::filesystem::path> files;
    for (std::size_t i = 0; i < json["recent"].size(); ++i) {
        const nlohmann::json& entry = json["recent"][i];
        if (!entry.is_string()) throw Error("recent[" + std::to_string(i) + "] is not a path string");
        files.emplace_back(entry.get<std::string>());
    }
    return files;
}

}  // namespace

std::optional<std::filesystem::path> recentFilesPath() {
    const char* config = std::getenv("XDG_CONFIG_HOME");
    if (config && *config) return std::filesystem::path(config) / "opal" / "recent.json";
    const char* home = std::getenv("HOME");
    if (home && *home) return std::filesystem::path(home) / ".config" / "opal" / "recent.json";
    return std::nullopt;
}

RecentFiles::RecentFiles(std::optional<std::filesystem::path> file) : file_(std::move(file)) {
    if (!file_ || !std::filesystem::exists(*file_)) return;
    try {
        files_ = readList(*file_);
        if (files_.size() > Limit) files_.resize(Limit);
    } catch (const std::exception& e) {
        warning_ = file_->string() + ": " + e.what() + "; the list of recent files starts empty";
        files_.clear();
    }
}

void RecentFiles::add(const std::filesystem::path& opened) {
    const std::filesystem::path file = std::filesystem::absolute(opened).lexically_normal();
    files_.erase(std::remove(files_.begin(), files_.end(), file), files_.end());
    files_.insert(files_.begin(), file);
    if (files_.size() > Limit) files_.resize(Limit);
    if (!file_) return;
    nlohmann::json list = nlohmann::json::array();
    for (const std::filesystem::path& f : files_) list.push_back(f.string());
    std::error_code error;
    std::filesystem::create_directories(file_->parent_path(), error);
    if (error) throw Error(file_->parent_path().string() + ": cannot make the folder: " + error.message());
    writeFileAtomically(*file_, nlohmann::json{{"recent", list}}.dump(2) + "\n");
}

}  // namespace opal::view
