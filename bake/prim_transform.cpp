#include "bake/prim_transform.h"

#include "schema/error.h"
#include "schema/usd/xform_op.h"

#include <algorithm>
#include <optional>
#include <string_view>

namespace opal {
namespace {

namespace types = usda::types;

constexpr std::string_view kOpPrefix = "xformOp:";

[[noreturn]] void fail(const usda::SourceLocation& where, const std::string& primPath, std::string_view property,
                       const std::string& problem) {
    throw Error(where.str() + ": <" + primPath + ">." + std::string(property) + ": " + problem);
}

// The matrix the entry of xformOpOrder contributes ("!invert!xformOp:translate:pivot").
Imath::M44d evaluateEntry(const usda::Prim& prim, const std::string& primPath, const usda::Attribute& order,
                          std::string_view entry) {
    const std::optional<usda::XformOpOrderEntry> op = usda::parseXformOpOrderEntry(entry);
    if (!op) {
        fail(order.location, primPath, order.name,
             "lists '" + std::string(entry) +
                 "', which is not a supported xformOp (supported: translate, scale, rotateX/Y/Z, rotateXYZ and other "
                 "orders, orient, transform)");
    }
    const usda::Attribute* attr = prim.findValue(op->opName, usda::xformOpValueTypes(op->type), "<" + primPath + ">");
    if (!attr) {
        fail(order.location, primPath, order.name,
             "lists '" + std::string(op->opName) + "', which the prim does not author with a value");
    }
    try {
        return usda::xformOpMatrix(*op, *attr->value);
    } catch (const Error& e) {
        fail(attr->location, primPath, op->opName, e.what());
    }
}

std::vector<std::string> unusedOps(const usda::Prim& prim, const std::vector<std::string>& order) {
    std::vector<std::string> unused;
    for (const usda::Property& p : prim.properties) {
        const std::string& name = usda::propertyName(p);
        if (!name.starts_with(kOpPrefix)) continue;
        const bool listed = std::any_of(order.begin(), order.end(), [&](const std::string& entry) {
            const std::optional<usda::XformOpOrderEntry> op = usda::parseXformOpOrderEntry(entry);
            return op && op->opName == name;
        });
        if (!listed) unused.push_back(name);
    }
    return unused;
}

}  // namespace

PrimTransform primTransform(const usda::Prim& prim, const std::string& primPath) {
    PrimTransform result;
    const usda::ValueType orderType[] = {types::TokenArray};
    const usda::Attribute* order = prim.findValue("xformOpOrder", orderType, "<" + primPath + ">");
    const std::vector<std::string> entries =
        order ? std::get<std::vector<std::string>>(order->value->data()) : std::vector<std::string>();
    // Listed first op acts last on points: each op multiplies from the left (row vectors).
    for (const std::string& entry : entries) {
        if (entry == usda::kResetXformStack) {  // as USD: the ops before it are dropped too
            result.resetsXformStack = true;
            result.local = Imath::M44d();
            continue;
        }
        result.local = evaluateEntry(prim, primPath, *order, entry) * result.local;
    }
    result.unusedOps = unusedOps(prim, entries);
    return result;
}

}  // namespace opal
