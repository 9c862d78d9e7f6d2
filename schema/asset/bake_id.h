// A bake's identifier: a 64-bit number the bake derives from everything that determines
// its result (bake/bake_identifier.h) and records in both halves of the asset, the
// layer's `opal:bakeId` and the sidecar's `BKID` chunk, so that a reader can tell a layer
// and a sidecar from different bakes apart even when they describe the same mesh. In text
// (the layer, the sidecar's file name, messages) it is 16 lowercase hexadecimal digits.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace opal {

inline constexpr std::size_t kBakeIdDigits = 16;

std::string formatBakeId(std::uint64_t id);

// The identifier `text` spells, or nullopt unless it is exactly 16 lowercase hex digits.
std::optional<std::uint64_t> parseBakeId(std::string_view text);

}  // namespace opal
