// A USD prim's local transform from its xformOps (UsdGeomXformable) as the bake reads
// them: the ops named in xformOpOrder, each evaluated by schema/usd/xform_op.h and composed
// in that order, with USD's leniency: a "!resetXformStack!" anywhere drops the ancestors'
// transforms and the ops listed before it, and xformOp:* attributes xformOpOrder does not
// list are ignored (reported, so the bake can warn). Matrices use USD's row-vector
// convention: for xformOpOrder = [translate, rotateXYZ, scale] the point is scaled first,
// M = S * R * T. A prim's world transform is local * parentWorld, or local alone when it
// resets the stack.
#pragma once

#include "schema/usd/usda_layer.h"

#include <Imath/ImathMatrix.h>

#include <string>
#include <vector>

namespace opal {

struct PrimTransform {
    Imath::M44d local;                    // identity when the prim has no xformOpOrder
    bool resetsXformStack = false;        // ignore the ancestors' transforms
    std::vector<std::string> unusedOps;   // xformOp:* attributes not in xformOpOrder (USD ignores them)
};

// Op types: those of usda::XformOpType, each with an optional ":suffix" and "!invert!"
// prefix. Throws opal::Error "file:line:column: </Path>.attr: problem" for anything else:
// an unknown op type, an op listed but not authored or blocked, a value of the wrong type,
// a zero quaternion, an inverted singular op.
PrimTransform primTransform(const usda::Prim& prim, const std::string& primPath);

}  // namespace opal
