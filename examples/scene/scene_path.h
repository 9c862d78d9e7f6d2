// Prim paths of a scene layer (Sdf's SdfPath, restricted to prim paths): built from prim
// names while the reader walks the layer, and resolved from relationship targets, which
// USDA may write absolute (</Looks/Wax>) or relative to the owning prim (<../Looks/Wax>).
#pragma once

#include "delegate/hd/types.h"

#include <string_view>

namespace opal::scene {

// "/World" + "Candle" -> "/World/Candle"; the root is "/".
hd::SdfPath childPath(const hd::SdfPath& parent, std::string_view name);

// The absolute prim path `target` names, relative targets resolved against `anchor` (the
// prim owning the relationship). Throws opal::Error (without a location: the caller adds
// the relationship's) for a property path (</Looks/Wax.outputs:surface>) or a relative
// path that climbs above the root.
hd::SdfPath resolveTargetPath(const hd::SdfPath& anchor, std::string_view target);

}  // namespace opal::scene
