#include "examples/scene/xformable.h"

#include "schema/usd/xform_op.h"

#include <optional>
#include <set>

namespace opal::scene {
namespace {

// The matrix of one xformOpOrder entry ("xformOp:scale" or "!invert!xformOp:translate:pivot").
Imath::M44d entryMatrix(PrimReader& reader, const usda::Attribute& order, const usda::XformOpOrderEntry& entry) {
    const usda::Attribute* op = reader.find(entry.opName, usda::xformOpValueTypes(entry.type));
    if (!op) reader.failAt(order, "lists " + quotedName(entry.opName) + ", which the prim does not author with a value");
    try {
        return usda::xformOpMatrix(entry, *op->value);
    } catch (const Error& e) {
        reader.failAt(*op, e.what());
    }
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
            if (entry == usda::kResetXformStack) {
                if (i != 0) reader.failAt(*order, "has " + quotedName(entry) + " after its first entry");
                local.resetsXformStack = true;
                continue;
            }
            if (!seen.insert(entry).second) reader.failAt(*order, "lists " + quotedName(entry) + " twice");
            const std::optional<usda::XformOpOrderEntry> op = usda::parseXformOpOrderEntry(entry);
            if (!op) reader.failAt(*order, "lists " + quotedName(entry) + ", which is not an xformOp name (see examples/SCENES.md)");
            // Listed ops are outermost first: each one applies after those listed after it.
            local.matrix = entryMatrix(reader, *order, *op) * local.matrix;
            listed.insert(op->opName);
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
