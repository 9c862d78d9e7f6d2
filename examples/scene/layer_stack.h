// A scene layer and its subLayers composed into one layer, as far as Opal's scene subset
// needs it to render an asset's over-layer stack (examples/SCENES.md#layer-stacks):
// `subLayers = [@./statue.over.usda@, @./statue.usda@]` over the user's layer.
//
// Strength: the scene layer, then each subLayer in the order listed, each followed by its
// own subLayers (depth first), as USD's layer stack. Prims compose by path:
// - the specifier is the strongest `def` or `class` (a prim only `over`s author stays an
//   over, and the scene reader refuses it);
// - the type name, each metadata key (dictionaries are not merged key by key), each
//   relationship and each attribute's value (default and timeSamples together) come from
//   the strongest layer that authors them; a declaration without a value takes the
//   weaker value;
// - apiSchemas and references compose as list ops (prepend and append over the weaker
//   list, an explicit list replaces it);
// - children are the union of every layer's.
// Layer metadata comes from the scene layer alone (so does USD's stage metadata). Asset
// paths (references, asset-valued attributes) authored in a subLayer elsewhere are
// re-anchored at the scene layer, so that they resolve as they would in their own layer.
// Refused with the file named: a subLayer that does not exist, and a cycle; the USDA
// reader refuses sublayer offsets.
#pragma once

#include "schema/usd/usda_layer.h"

#include <filesystem>

namespace opal::scene {

usda::Layer composeLayerStack(const std::filesystem::path& file);

}  // namespace opal::scene
