// Opal's one evaluation of a UsdGeomXformOp: its type (from the attribute name
// "xformOp:<type>[:<suffix>]"), the value types USD allows it, the entries of xformOpOrder
// that name it, and its matrix. Matrices use USD's and Imath's row-vector convention
// (p' = p M, translation in row 3); angles are in degrees, rotations right-handed, exactly
// as UsdGeomXformOp::GetOpTransform computes them. A prim's local matrix is the product of
// its ops' matrices in the reverse of xformOpOrder (the first listed acts last on points);
// the readers that compose them (the bake's USDA import, the scene reader) differ only in
// how strictly they treat what USD ignores.
#pragma once

#include "schema/usd/usda_value.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathQuat.h>
#include <Imath/ImathVec.h>

#include <optional>
#include <span>
#include <string_view>

namespace opal::usda {

enum class XformOpType {
    Translate, Scale,
    RotateX, RotateY, RotateZ,
    RotateXYZ, RotateXZY, RotateYXZ, RotateYZX, RotateZXY, RotateZYX,
    Orient, Transform,
};

// "xformOp:rotateXYZ" and "xformOp:rotateXYZ:tilt" -> RotateXYZ; nullopt for any other
// name (no "xformOp:" prefix, an unknown type, an empty suffix).
std::optional<XformOpType> parseXformOpName(std::string_view attributeName);

// The declared types USD accepts (half precision is outside Opal's USDA subset):
// float3/double3 for translate, scale and the three-axis rotations, float/double for
// single-axis rotations, quatf/quatd for orient, matrix4d for transform.
std::span<const ValueType> xformOpValueTypes(XformOpType type);

inline constexpr std::string_view kResetXformStack = "!resetXformStack!";

// One entry of xformOpOrder other than kResetXformStack: "xformOp:scale", or
// "!invert!xformOp:translate:pivot" for the op's inverse.
struct XformOpOrderEntry {
    std::string_view opName;  // the attribute: "xformOp:translate:pivot"
    XformOpType type;
    bool inverted = false;
};
// nullopt when `entry` (without its "!invert!") is not an op name (parseXformOpName).
std::optional<XformOpOrderEntry> parseXformOpOrderEntry(std::string_view entry);

Imath::M44d translateMatrix(const Imath::V3d& offset);
Imath::M44d scaleMatrix(const Imath::V3d& factors);
// About axis 0 (X), 1 (Y) or 2 (Z), counter-clockwise looking down the axis.
Imath::M44d rotateMatrix(int axis, double degrees);
// The three-axis rotations: `degrees` is always (x, y, z); rotateXYZ turns a point about
// X first, then Y, then Z, so its matrix is Rx Ry Rz (and so on for the other orders).
Imath::M44d rotateEulerMatrix(XformOpType type, const Imath::V3d& degrees);
// Orientation by a quaternion (real part w); normalized first. Throws opal::Error "is a
// zero quaternion".
Imath::M44d orientMatrix(double w, const Imath::V3d& imaginary);

// The matrix of an op of `type` whose value is `value` (one of xformOpValueTypes(type)).
Imath::M44d xformOpMatrix(XformOpType type, const Value& value);
// The matrix an xformOpOrder entry contributes: its op's, inverted when the entry says so.
// Throws opal::Error "is singular and cannot be inverted (<entry>)" for an inverted op
// without an inverse, and as xformOpMatrix.
Imath::M44d xformOpMatrix(const XformOpOrderEntry& entry, const Value& value);

}  // namespace opal::usda
