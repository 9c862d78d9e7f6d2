// A USD prim's local transform from its xformOps (UsdGeomXformable): the ops named in
// xformOpOrder, composed in that order. Matrices use USD's row-vector convention, which
// Imath shares: p' = p * M, translation in row 3, and for xformOpOrder = [translate,
// rotateXYZ, scale] the point is scaled first: M = S * R * T. A prim's world transform is
// local * parentWorld, or local alone when the order starts with "!resetXformStack!".
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

// Op types: translate, translateX/Y/Z, scale, scaleX/Y/Z, rotateX/Y/Z (degrees),
// rotateXYZ and the five other orders (first letter's axis applied first), orient
// (quaternion, real part first) and transform (matrix4d); each with an optional
// ":suffix" and "!invert!" prefix. Throws opal::Error "file:line:column: </Path>.attr:
// problem" for anything else: an unknown op type, an op listed but not authored or
// blocked, a value of the wrong type, a zero quaternion, an inverted singular op.
PrimTransform primTransform(const usda::Prim& prim, const std::string& primPath);

}  // namespace opal
