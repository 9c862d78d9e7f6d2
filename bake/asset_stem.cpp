#include "bake/asset_stem.h"

#include "schema/asset/bake_id.h"
#include "schema/usd/crash_point.h"

#include <system_error>

namespace opal {
namespace {

constexpr std::string_view kTemporaryMark = ".tmp-";  // AtomicFileWriter's temporary names

void removeFile(const std::filesystem::path& file, std::vector<std::string>* warnings) {
    std::error_code error;
    std::filesystem::remove(file, error);
    if (error && warnings) warnings->push_back(file.string() + ": cannot remove it: " + error.message());
}

}  // namespace

AssetStem::AssetStem(std::filesystem::path stem) : stem_(std::move(stem)), name_(stem_.filename().string()) {}

std::filesystem::path AssetStem::layer() const {
    std::filesystem::path p = stem_;
    return p += ".usda";
}

std::filesystem::path AssetStem::sidecar(std::uint64_t bakeId) const {
    std::string name = name_;
    name += '.';
    name += formatBakeId(bakeId);
    name += ".opal";
    return stem_.parent_path() / name;
}

std::filesystem::path AssetStem::lockFile() const {
    std::filesystem::path p = stem_;
    return p += ".lock";
}

std::optional<std::string_view> AssetStem::suffix(std::string_view fileName) const {
    if (fileName.size() <= name_.size() + 1 || !fileName.starts_with(name_) || fileName[name_.size()] != '.')
        return std::nullopt;
    return fileName.substr(name_.size() + 1);
}

// "opal" or "<16 hex digits>.opal" after "<stem>.": a stem "candle.v2" has sidecars
// "candle.v2.<id>.opal", which this rule never takes for "candle"'s.
bool AssetStem::isSidecar(std::string_view fileName) const {
    const std::optional<std::string_view> rest = suffix(fileName);
    if (!rest) return false;
    if (*rest == "opal") return true;
    return rest->size() == kBakeIdDigits + 5 && rest->ends_with(".opal") &&
           parseBakeId(rest->substr(0, kBakeIdDigits)).has_value();
}

bool AssetStem::isTemporary(std::string_view fileName) const {
    const std::size_t mark = fileName.find(kTemporaryMark);
    if (mark == std::string_view::npos) return false;
    const std::string_view target = fileName.substr(0, mark);
    return isSidecar(target) || target == layer().filename().string();
}

template <class Predicate>
std::vector<std::filesystem::path> AssetStem::filesWhere(Predicate keepIt) const {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path folder = stem_.has_parent_path() ? stem_.parent_path() : ".";
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (keepIt(entry.path().filename().string())) files.push_back(entry.path());
    return files;
}

void AssetStem::removeStaleTemporaries(std::vector<std::string>* warnings) const {
    for (const std::filesystem::path& file : filesWhere([&](const std::string& n) { return isTemporary(n); }))
        removeFile(file, warnings);
}

void AssetStem::removeSidecarsExcept(std::uint64_t keep, std::vector<std::string>* warnings) const {
    const std::string kept = sidecar(keep).filename().string();
    for (const std::filesystem::path& file :
         filesWhere([&](const std::string& n) { return isSidecar(n) && n != kept; })) {
        removeFile(file, warnings);
        crashPoint("bake:pruned-one");
    }
}

}  // namespace opal
