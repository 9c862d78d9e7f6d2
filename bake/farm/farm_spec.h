// What a farm bake bakes (spec.task, written by the opal-bake that submits it) and what its
// prepare task hands the others (prepared.task: the asset without its transfer and
// environment, and the warnings so far). Both are task files (task_file.h) of one section.
#pragma once

#include "bake/bake_pipeline.h"
#include "bake/farm/farm_stage.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace opal {

struct FarmSpec {
    BakeOptions options;
    std::string stem;              // the asset's stem, as given
    std::string workingDirectory;  // where opal-bake was run: relative paths resolve here
    std::uint32_t shards = 1;
};

void writeFarmSpec(const FarmFolder& folder, const FarmSpec& spec);
FarmSpec readFarmSpec(const FarmFolder& folder);
// The bytes writeFarmSpec writes (the same spec, the same bytes): how a re-submitted bake
// recognizes the one whose tasks it can resume.
std::string encodeFarmSpec(const FarmSpec& spec);

struct PreparedBake {
    TranslucentAsset asset;  // without transfer and environment
    std::vector<std::string> warnings;
};

void writePreparedBake(const FarmFolder& folder, const PreparedBake& prepared);
PreparedBake readPreparedBake(const FarmFolder& folder);

}  // namespace opal
