#include "bake/farm/farm_stage.h"

#include "schema/error.h"

#include <cstdio>

namespace opal {

std::string_view stageName(FarmStage stage) {
    switch (stage) {
    case FarmStage::Prepare: return "prepare";
    case FarmStage::Rows: return "rows";
    case FarmStage::Columns: return "columns";
    case FarmStage::Keep: return "keep";
    case FarmStage::Merge: return "merge";
    }
    return "?";
}

std::optional<FarmStage> parseStage(std::string_view name) {
    for (FarmStage s : kFarmStages)
        if (stageName(s) == name) return s;
    return std::nullopt;
}

std::uint32_t taskCount(FarmStage stage, std::uint32_t shards) {
    return stage == FarmStage::Prepare || stage == FarmStage::Merge ? 1 : shards;
}

std::pair<std::size_t, std::size_t> shardRange(std::size_t n, std::uint32_t shards, std::uint32_t i) {
    if (shards == 0 || i >= shards)
        throw Error("farm: shard " + std::to_string(i) + " of " + std::to_string(shards) + " does not exist");
    return {n * i / shards, n * (std::size_t(i) + 1) / shards};
}

FarmFolder FarmFolder::forStem(const std::filesystem::path& stem) {
    return FarmFolder(std::filesystem::path(stem.string() + ".farm"));
}

std::filesystem::path FarmFolder::output(FarmStage stage, std::uint32_t i) const {
    if (stage == FarmStage::Prepare) return path_ / "prepared.task";
    char name[64];
    std::snprintf(name, sizeof name, "%s-%04u.task", std::string(stageName(stage)).c_str(), i);
    return path_ / name;
}

std::filesystem::path FarmFolder::log(FarmStage stage, std::uint32_t i) const {
    return logs() / (std::string(stageName(stage)) + "-" + std::to_string(i) + ".log");
}

std::filesystem::path FarmFolder::stats(FarmStage stage, std::uint32_t i) const {
    return path_ / "stats" / (std::string(stageName(stage)) + "-" + std::to_string(i));
}

std::string taskName(FarmStage stage, std::uint32_t i) {
    return std::string(stageName(stage)) + " " + std::to_string(i);
}

}  // namespace opal
