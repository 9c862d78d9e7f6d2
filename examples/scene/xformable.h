// The local transformation of an Xformable prim (UsdGeomXformable). `xformOpOrder` lists
// the ops outermost first: ["xformOp:translate", "xformOp:rotateXYZ", "xformOp:scale"]
// scales a point, then rotates it, then translates it, so with row vectors the local
// matrix is S R T, i.e. the product of the op matrices in reverse order (USD's
// GetLocalTransformation). "!invert!xformOp:..." uses the op's inverse (pivots), and a
// leading "!resetXformStack!" stops the parent's transformation from being inherited.
#pragma once

#include "examples/scene/prim_reader.h"

#include <Imath/ImathMatrix.h>

namespace opal::scene {

struct LocalTransform {
    Imath::M44d matrix;             // object to parent space, row vectors
    bool resetsXformStack = false;  // the object-to-world matrix is `matrix` alone
};

// Reads xformOpOrder and every op it names. Throws UsdaError at the attribute for an
// entry that is not an op name, an op listed twice, an op that is not authored or has no
// value, a value type USD does not allow for the op, an !invert! of a singular op, a
// misplaced !resetXformStack!, and any xformOp:* attribute xformOpOrder does not list
// (USD would ignore it silently).
LocalTransform readLocalTransform(PrimReader& reader);

// For prims that have no transformation (Scope, Material, RenderSettings, typeless
// groups): throws UsdaError at the first xformOpOrder or xformOp:* attribute.
void rejectTransform(PrimReader& reader);

}  // namespace opal::scene
