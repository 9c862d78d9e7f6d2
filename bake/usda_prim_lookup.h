// The one Mesh prim `opal-bake --apply-to </Path/To/Mesh>` bakes: found by path in a USDA
// layer, and refused unless USD would render it from that layer alone. Every prim on the
// path must be a `def` (a `class` is abstract, an `over` defines nothing in a lone layer),
// active, and without references (Opal does not compose them); the last one a Mesh.
#pragma once

#include "schema/usd/usda_layer.h"

#include <string>

namespace opal {

// Throws opal::Error "file:line:column: </World/Box>: problem" at the prim in the way (the
// file alone for a missing root prim or a malformed path).
const usda::Prim& findBakeablePrim(const usda::Layer& layer, const std::string& file, const std::string& primPath);

}  // namespace opal
