#include "examples/scene/xformable.h"

#include "examples/scene/xform_op.h"

#include <cmath>
#include <set>

namespace opal::scene {
namespace {

constexpr std::string_view InvertPrefix = "!invert!";
constexpr std::string_view ResetXformStack = "!resetXformStack!";

// The matrix of one xformOpOrder entry ("xformOp:scale" or "!invert!xformOp:translate:pivot").
Imath::M44d entryMatrix(PrimReader& reader, const usda::Attribute& order, std::string_view entry) {
    const bool invert = entry.starts_with(InvertPrefix);
    const std::string_view name = invert ? entry.substr(InvertPrefix.size()) : entry;
    const std::optional<XformOpType> type = parseXformOpName(name);
    if (!type) reader.failAt(order, "lists " + quotedName(entry) + ", which is not an xformOp name (see examples/SCENES.md)");
    const usda::Attribute* op = reader.find(name, xformOpValueTypes(*type));
    if (!op) reader.failAt(order, "lists " + quotedName(name) + ", which the prim does not author with a value");
    Imath::M44d m;
    try {
        m = xformOpMatrix(*type, *op->value);
    } catch (const Error& e) {
        reader.failAt(*op, e.what());
    }
    if (!invert) return m;
    if (std::abs(m.determinant()) < 1e-300) reader.failAt(*op, "is singular and cannot be inverted (" + std::string(entry) + ")");
    return m.inverse();
}

void requireListed(const PrimReader& reader, const std::set<std::string_view>& listed) {
    for (const usda::Property* p : reader.withPrefix("xformOp:"))
        if (!listed.count(usda::propertyName(*p)))
            reader.fail(usda::propertyLocation(*p), quotedName(usda::propertyName(*p)) +
                                                        " is not listed in xformOpOrder (USD would ignore it)");
}

}  // namespace

LocalTransform readLocalTransform(PrimReader& reader) {
    LocalTransform local;
    const usda::Attribute* order = reader.find("xformOpOrder", {usda::types::TokenArray});
    std::set<std::string_view> seen, listed;  // entries as written; the op attributes they name
    if (order) {
        const auto& entries = std::get<std::vector<std::string>>(order->value->data());
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const std::string_view entry = entries[i];
            if (entry == ResetXformStack) {
                if (i != 0) reader.failAt(*order, "has " + quotedName(entry) + " after its first entry");
                local.resetsXformStack = true;
                continue;
            }
            if (!seen.insert(entry).second) reader.failAt(*order, "lists " + quotedName(entry) + " twice");
            // Listed ops are outermost first: each one applies after those listed after it.
            local.matrix = entryMatrix(reader, *order, entry) * local.matrix;
            listed.insert(entry.starts_with(InvertPrefix) ? entry.substr(InvertPrefix.size()) : entry);
        }
    }
    requireListed(reader, listed);
    return local;
}

void rejectTransform(PrimReader& reader) {
    const auto ops = reader.withPrefix("xformOp");
    if (ops.empty()) return;
    reader.fail(usda::propertyLocation(*ops.front()),
                quotedName(usda::propertyName(*ops.front())) + ": this prim type has no transformation (use an Xform)");
}

}  // namespace opal::scene
