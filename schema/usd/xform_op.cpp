#include "schema/usd/xform_op.h"

#include "schema/error.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace opal::usda {
namespace {

constexpr std::string_view kInvertPrefix = "!invert!";

struct OpName {
    std::string_view name;
    XformOpType type;
};

constexpr std::array<OpName, 13> OpNames = {{
    {"translate", XformOpType::Translate}, {"scale", XformOpType::Scale},
    {"rotateX", XformOpType::RotateX},     {"rotateY", XformOpType::RotateY},
    {"rotateZ", XformOpType::RotateZ},     {"rotateXYZ", XformOpType::RotateXYZ},
    {"rotateXZY", XformOpType::RotateXZY}, {"rotateYXZ", XformOpType::RotateYXZ},
    {"rotateYZX", XformOpType::RotateYZX}, {"rotateZXY", XformOpType::RotateZXY},
    {"rotateZYX", XformOpType::RotateZYX}, {"orient", XformOpType::Orient},
    {"transform", XformOpType::Transform},
}};

constexpr std::array<ValueType, 2> Vector3Types = {types::Float3, types::Double3};
constexpr std::array<ValueType, 2> ScalarTypes = {types::Float, types::Double};
constexpr std::array<ValueType, 2> QuatTypes = {types::Quatf, types::Quatd};
constexpr std::array<ValueType, 1> MatrixTypes = {types::Matrix4d};

// The axes of a three-axis rotation in the order they turn a point: rotateYXZ -> Y, X, Z.
std::array<int, 3> eulerAxes(XformOpType type) {
    switch (type) {
        case XformOpType::RotateXYZ: return {0, 1, 2};
        case XformOpType::RotateXZY: return {0, 2, 1};
        case XformOpType::RotateYXZ: return {1, 0, 2};
        case XformOpType::RotateYZX: return {1, 2, 0};
        case XformOpType::RotateZXY: return {2, 0, 1};
        case XformOpType::RotateZYX: return {2, 1, 0};
        default: throw Error("rotateEulerMatrix: not a three-axis rotation");
    }
}

Imath::V3d vector3(const Value& value) {
    if (const auto* f = std::get_if<Vec3f>(&value.data())) return {(*f)[0], (*f)[1], (*f)[2]};
    const auto& d = std::get<Vec3d>(value.data());
    return {d[0], d[1], d[2]};
}

double scalar(const Value& value) {
    if (const auto* f = std::get_if<float>(&value.data())) return *f;
    return std::get<double>(value.data());
}

}  // namespace

std::optional<XformOpType> parseXformOpName(std::string_view attributeName) {
    constexpr std::string_view prefix = "xformOp:";
    if (!attributeName.starts_with(prefix)) return std::nullopt;
    std::string_view rest = attributeName.substr(prefix.size());
    const std::size_t colon = rest.find(':');
    if (colon != std::string_view::npos && colon + 1 == rest.size()) return std::nullopt;
    const std::string_view typeName = rest.substr(0, colon);
    for (const OpName& op : OpNames)
        if (op.name == typeName) return op.type;
    return std::nullopt;
}

std::optional<XformOpOrderEntry> parseXformOpOrderEntry(std::string_view entry) {
    const bool inverted = entry.starts_with(kInvertPrefix);
    const std::string_view opName = inverted ? entry.substr(kInvertPrefix.size()) : entry;
    const std::optional<XformOpType> type = parseXformOpName(opName);
    if (!type) return std::nullopt;
    return XformOpOrderEntry{opName, *type, inverted};
}

std::span<const ValueType> xformOpValueTypes(XformOpType type) {
    switch (type) {
        case XformOpType::RotateX:
        case XformOpType::RotateY:
        case XformOpType::RotateZ: return ScalarTypes;
        case XformOpType::Orient: return QuatTypes;
        case XformOpType::Transform: return MatrixTypes;
        default: return Vector3Types;
    }
}

// Imath's own: row-vector matrices, the translation in the last row.
Imath::M44d translateMatrix(const Imath::V3d& offset) { return Imath::M44d().setTranslation(offset); }

Imath::M44d scaleMatrix(const Imath::V3d& factors) { return Imath::M44d().setScale(factors); }

Imath::M44d rotateMatrix(int axis, double degrees) {
    const double radians = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(radians), s = std::sin(radians);
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // the plane turned: u towards v
    Imath::M44d m;
    m[u][u] = c;
    m[u][v] = s;
    m[v][u] = -s;
    m[v][v] = c;
    return m;
}

Imath::M44d rotateEulerMatrix(XformOpType type, const Imath::V3d& degrees) {
    Imath::M44d m;
    for (int axis : eulerAxes(type)) m = m * rotateMatrix(axis, degrees[axis]);
    return m;
}

Imath::M44d orientMatrix(double w, const Imath::V3d& imaginary) {
    const double norm = std::sqrt(w * w + imaginary.length2());
    if (!(norm > 0.0)) throw Error("is a zero quaternion");
    const double r = w / norm, x = imaginary.x / norm, y = imaginary.y / norm, z = imaginary.z / norm;
    // The rotation of q v q* as a column-vector matrix, transposed for row vectors.
    Imath::M44d m;
    m[0][0] = 1 - 2 * (y * y + z * z);
    m[1][0] = 2 * (x * y - r * z);
    m[2][0] = 2 * (x * z + r * y);
    m[0][1] = 2 * (x * y + r * z);
    m[1][1] = 1 - 2 * (x * x + z * z);
    m[2][1] = 2 * (y * z - r * x);
    m[0][2] = 2 * (x * z - r * y);
    m[1][2] = 2 * (y * z + r * x);
    m[2][2] = 1 - 2 * (x * x + y * y);
    return m;
}

Imath::M44d xformOpMatrix(XformOpType type, const Value& value) {
    switch (type) {
        case XformOpType::Translate: return translateMatrix(vector3(value));
        case XformOpType::Scale: return scaleMatrix(vector3(value));
        case XformOpType::RotateX: return rotateMatrix(0, scalar(value));
        case XformOpType::RotateY: return rotateMatrix(1, scalar(value));
        case XformOpType::RotateZ: return rotateMatrix(2, scalar(value));
        case XformOpType::Orient: {
            if (const auto* f = std::get_if<Vec4f>(&value.data()))
                return orientMatrix((*f)[0], {(*f)[1], (*f)[2], (*f)[3]});
            const auto& d = std::get<Vec4d>(value.data());
            return orientMatrix(d[0], {d[1], d[2], d[3]});
        }
        case XformOpType::Transform: {
            const auto& rows = std::get<Matrix4d>(value.data());
            Imath::M44d m;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) m[r][c] = rows[r][c];
            return m;
        }
        default: return rotateEulerMatrix(type, vector3(value));
    }
}

Imath::M44d xformOpMatrix(const XformOpOrderEntry& entry, const Value& value) {
    const Imath::M44d m = xformOpMatrix(entry.type, value);
    if (!entry.inverted) return m;
    const double determinant = m.determinant();
    if (!(std::abs(determinant) >= 1e-300) || !std::isfinite(determinant))
        throw Error("is singular and cannot be inverted (" + std::string(kInvertPrefix) + std::string(entry.opName) + ")");
    return m.inverse();
}

}  // namespace opal::usda
