#include "bake/usda_prim_lookup.h"

#include "schema/error.h"

#include <vector>

namespace opal {
namespace {

std::vector<std::string> pathElements(const std::string& file, const std::string& primPath) {
    std::vector<std::string> names;
    const auto bad = [&](const std::string& why) {
        throw Error(file + ": --apply-to <" + primPath + ">: " + why + " (expected an absolute prim path, "
                    "e.g. /World/Statue)");
    };
    if (primPath.size() < 2 || primPath[0] != '/') bad("not an absolute prim path");
    std::size_t start = 1;
    while (start <= primPath.size()) {
        const std::size_t end = std::min(primPath.find('/', start), primPath.size());
        if (end == start) bad("an empty prim name");
        names.push_back(primPath.substr(start, end - start));
        start = end + 1;
    }
    return names;
}

std::string childNames(const std::vector<usda::Prim>& prims) {
    std::string names;
    for (const usda::Prim& p : prims) names += (names.empty() ? "" : ", ") + p.name;
    return names.empty() ? "none" : names;
}

[[noreturn]] void failAt(const usda::Prim& prim, const std::string& path, const std::string& problem) {
    throw Error(prim.location.str() + ": <" + path + ">: " + problem);
}

// A prim on the way to the Mesh: USD renders what is below it only if it is a def, active,
// and the layer alone says everything about it.
void checkOnPath(const usda::Prim& prim, const std::string& path) {
    if (prim.specifier == usda::Specifier::Class)
        failAt(prim, path, "is a class prim: abstract, USD never renders it or what it holds");
    if (prim.specifier == usda::Specifier::Over)
        failAt(prim, path, "is an over prim: in this layer alone it defines nothing; bake the layer that defines it");
    const usda::Value* active = prim.metadata.find("active");
    if (active && !active->get<usda::types::Bool>("metadata 'active'"))
        failAt(prim, path, "is inactive (active = false): USD does not render it or what it holds");
    if (prim.references.authored())
        failAt(prim, path, "has references, which Opal does not compose: flatten the layer first (usdcat --flatten)");
}

}  // namespace

const usda::Prim& findBakeablePrim(const usda::Layer& layer, const std::string& file, const std::string& primPath) {
    const std::vector<std::string> names = pathElements(file, primPath);
    const std::vector<usda::Prim>* children = &layer.rootPrims;
    const usda::Prim* prim = nullptr;
    std::string path;
    for (const std::string& name : names) {
        const usda::Prim* next = nullptr;
        for (const usda::Prim& child : *children)
            if (child.name == name) next = &child;
        if (!next && !prim)
            throw Error(file + ": --apply-to <" + primPath + ">: the layer has no root prim '" + name +
                        "' (its root prims: " + childNames(*children) + ")");
        if (!next)
            failAt(*prim, path, "has no child prim '" + name + "' (--apply-to <" + primPath +
                                    ">; its children: " + childNames(*children) + ")");
        path += "/" + name;
        prim = next;
        checkOnPath(*prim, path);
        children = &prim->children;
    }
    if (prim->typeName != "Mesh")
        failAt(*prim, path, (prim->typeName.empty() ? std::string("is a typeless prim")
                                                    : "is a " + prim->typeName + " prim") +
                                ", not a Mesh: --apply-to bakes one Mesh prim");
    return *prim;
}

}  // namespace opal
