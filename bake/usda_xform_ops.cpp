#include "bake/usda_xform_ops.h"

#include "schema/error.h"

#include <Imath/ImathQuat.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>
#include <type_traits>
#include <variant>

namespace opal {
namespace {

namespace types = usda::types;

constexpr std::string_view kOpPrefix = "xformOp:";
constexpr std::string_view kInvert = "!invert!";
constexpr std::string_view kResetXformStack = "!resetXformStack!";

[[noreturn]] void fail(const usda::SourceLocation& where, const std::string& primPath, std::string_view property,
                       const std::string& problem) {
    throw Error(where.str() + ": <" + primPath + ">." + std::string(property) + ": " + problem);
}

bool isAxis(char c) { return c == 'X' || c == 'Y' || c == 'Z'; }

Imath::V3d axis(char c) {
    return c == 'X' ? Imath::V3d(1, 0, 0) : c == 'Y' ? Imath::V3d(0, 1, 0) : Imath::V3d(0, 0, 1);
}

// "rotateXYZ", "rotateZXY", ...: three distinct axes.
bool isThreeAxisRotation(std::string_view type) {
    if (type.size() != 9 || !type.starts_with("rotate")) return false;
    const char a = type[6], b = type[7], c = type[8];
    return isAxis(a) && isAxis(b) && isAxis(c) && a != b && b != c && a != c;
}

bool isOneAxisRotation(std::string_view type) {
    return type.size() == 7 && type.starts_with("rotate") && isAxis(type[6]);
}

// The value types each op type may be declared with; empty for an op type USD lacks.
std::vector<usda::ValueType> acceptedTypes(std::string_view type) {
    if (type == "transform") return {types::Matrix4d};
    if (type == "orient") return {types::Quatf, types::Quatd};
    if (type == "translate" || type == "scale" || isThreeAxisRotation(type)) return {types::Double3, types::Float3};
    if (isOneAxisRotation(type)) return {types::Double, types::Float};
    return {};
}

// The numbers of a scalar, tuple or matrix value, as doubles (a matrix row by row).
std::vector<double> numbersOf(const usda::Value& value) {
    return std::visit(
        [](const auto& data) -> std::vector<double> {
            using D = std::decay_t<decltype(data)>;
            if constexpr (std::is_same_v<D, float> || std::is_same_v<D, double>) {
                return {double(data)};
            } else if constexpr (std::is_same_v<D, usda::Vec3f> || std::is_same_v<D, usda::Vec3d> ||
                                 std::is_same_v<D, usda::Vec4f> || std::is_same_v<D, usda::Vec4d>) {
                return std::vector<double>(data.begin(), data.end());
            } else if constexpr (std::is_same_v<D, usda::Matrix4d>) {
                std::vector<double> all;
                for (const usda::Vec4d& row : data) all.insert(all.end(), row.begin(), row.end());
                return all;
            } else {
                return {};
            }
        },
        value.data());
}

// Rotation by `degrees` about `a`, counter-clockwise seen from the axis' tip (GfRotation).
Imath::M44d rotation(const Imath::V3d& a, double degrees) {
    Imath::Quatd q;
    q.setAxisAngle(a, degrees * std::numbers::pi / 180.0);
    return q.toMatrix44();
}

// One op's matrix. `n` holds as many numbers as the accepted type has (checked before).
Imath::M44d opMatrix(std::string_view type, const std::vector<double>& n) {
    Imath::M44d m;  // identity
    if (type == "translate") {
        m.setTranslation(Imath::V3d(n[0], n[1], n[2]));
    } else if (type == "scale") {
        m.setScale(Imath::V3d(n[0], n[1], n[2]));
    } else if (isOneAxisRotation(type)) {
        m = rotation(axis(type[6]), n[0]);
    } else if (isThreeAxisRotation(type)) {
        // rotateXYZ = (x, y, z) degrees, X applied first: M = Rx * Ry * Rz (row vectors).
        const std::string_view axes = type.substr(6);
        const std::string_view names = "XYZ";
        for (char a : axes) m = m * rotation(axis(a), n[names.find(a)]);
    } else if (type == "orient") {
        m = Imath::Quatd(n[0], n[1], n[2], n[3]).normalized().toMatrix44();
    } else {  // transform: rows as written
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m[r][c] = n[std::size_t(4 * r + c)];
    }
    return m;
}

std::string acceptedNames(const std::vector<usda::ValueType>& accepted) {
    std::string names;
    for (usda::ValueType t : accepted) names += (names.empty() ? "" : " or ") + usda::typeName(t);
    return names;
}

// The matrix of the op `entry` of xformOpOrder names ("!invert!xformOp:translate:pivot").
Imath::M44d evaluateOp(const usda::Prim& prim, const std::string& primPath, const usda::Attribute& order,
                       std::string_view entry) {
    const bool invert = entry.starts_with(kInvert);
    const std::string_view name = invert ? entry.substr(kInvert.size()) : entry;
    if (!name.starts_with(kOpPrefix)) {
        fail(order.location, primPath, order.name, "'" + std::string(entry) + "' is not an xformOp");
    }
    const std::string_view rest = name.substr(kOpPrefix.size());
    const std::string_view type = rest.substr(0, rest.find(':'));
    const std::vector<usda::ValueType> accepted = acceptedTypes(type);
    if (accepted.empty()) {
        fail(order.location, primPath, order.name,
             "unsupported xformOp type '" + std::string(type) +
                 "' (supported: translate, scale, rotateX/Y/Z, rotateXYZ and other orders, orient, transform)");
    }
    const usda::Attribute* attr = prim.findAttribute(name);
    if (!attr) {
        fail(order.location, primPath, order.name,
             "lists '" + std::string(name) + "' but the prim has no such attribute");
    }
    if (!attr->hasValue()) fail(attr->location, primPath, name, "has no value (it is listed in xformOpOrder)");
    if (std::find(accepted.begin(), accepted.end(), attr->value->type()) == accepted.end()) {
        fail(attr->location, primPath, name,
             "has type " + usda::typeName(attr->value->type()) + ", expected " + acceptedNames(accepted));
    }
    const std::vector<double> n = numbersOf(*attr->value);
    if (type == "orient" && n[0] == 0 && n[1] == 0 && n[2] == 0 && n[3] == 0) {
        fail(attr->location, primPath, name, "the quaternion is zero");
    }
    const Imath::M44d m = opMatrix(type, n);
    if (!invert) return m;
    const double det = m.determinant();
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) {
        fail(attr->location, primPath, name, "!invert! of a singular op");
    }
    return m.gjInverse();
}

std::vector<std::string> unusedOps(const usda::Prim& prim, const std::vector<std::string>& order) {
    std::vector<std::string> unused;
    for (const usda::Property& p : prim.properties) {
        const std::string& name = usda::propertyName(p);
        if (!name.starts_with(kOpPrefix)) continue;
        const bool listed = std::any_of(order.begin(), order.end(), [&](const std::string& entry) {
            return entry == name ||
                   (entry.starts_with(kInvert) && std::string_view(entry).substr(kInvert.size()) == name);
        });
        if (!listed) unused.push_back(name);
    }
    return unused;
}

}  // namespace

PrimTransform primTransform(const usda::Prim& prim, const std::string& primPath) {
    PrimTransform result;
    const usda::Attribute* order = prim.findAttribute("xformOpOrder");
    std::vector<std::string> entries;
    if (order && order->hasValue()) {
        if (!order->value->is<types::TokenArray>()) {
            fail(order->location, primPath, order->name,
                 "has type " + usda::typeName(order->value->type()) + ", expected token[]");
        }
        entries = order->value->get<types::TokenArray>("attribute 'xformOpOrder'");
    }
    // Listed first op acts last on points: each op multiplies from the left (row vectors).
    for (const std::string& entry : entries) {
        if (entry == kResetXformStack) {  // as USD: the ops before it are dropped too
            result.resetsXformStack = true;
            result.local = Imath::M44d();
            continue;
        }
        result.local = evaluateOp(prim, primPath, *order, entry) * result.local;
    }
    result.unusedOps = unusedOps(prim, entries);
    return result;
}

}  // namespace opal
