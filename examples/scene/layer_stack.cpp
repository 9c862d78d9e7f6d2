#include "examples/scene/layer_stack.h"

#include "examples/scene/asset_path.h"
#include "schema/usd/usda_reader.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace opal::scene {
namespace {

// A layer of the stack, strongest first, with the file its asset paths are anchored at.
struct StackLayer {
    usda::Layer layer;
    std::filesystem::path file;
};

std::string chainText(const std::vector<std::filesystem::path>& chain, const std::filesystem::path& last) {
    std::string text;
    for (const std::filesystem::path& f : chain) text += f.string() + " -> ";
    return text + last.string();
}

void readStack(const std::filesystem::path& file, std::vector<std::filesystem::path>& chain,
               std::vector<StackLayer>& stack) {
    usda::Layer layer = usda::readUsdaFile(file);
    // weakly_canonical: a cycle through a symbolic link is a cycle too.
    chain.push_back(std::filesystem::weakly_canonical(std::filesystem::absolute(file)));
    const std::vector<std::string> subLayers = layer.subLayers;
    const usda::SourceLocation where = layer.location;
    stack.push_back({std::move(layer), file});
    for (const std::string& asset : subLayers) {
        const std::filesystem::path sub = resolveAssetPath(file, asset);
        if (std::find(chain.begin(), chain.end(), std::filesystem::weakly_canonical(sub)) != chain.end())
            throw usda::UsdaError(where, "subLayers: @" + asset + "@ makes a cycle (" + chainText(chain, sub) + ")");
        std::error_code error;
        if (!std::filesystem::is_regular_file(sub, error))
            throw usda::UsdaError(where, "subLayers: @" + asset + "@ does not exist (resolved to " + sub.string() + ")");
        readStack(sub, chain, stack);
    }
    chain.pop_back();
}

// Asset paths authored in `from` rewritten to resolve the same from `to`.
class Reanchor {
public:
    Reanchor(const std::filesystem::path& from, const std::filesystem::path& to)
        : from_(from), toDir_(std::filesystem::absolute(to).lexically_normal().parent_path()),
          needed_(std::filesystem::absolute(from).lexically_normal().parent_path() != toDir_) {}

    void prims(std::vector<usda::Prim>& prims) const {
        if (!needed_) return;
        for (usda::Prim& prim : prims) this->prim(prim);
    }

private:
    std::string path(const std::string& asset) const {
        if (asset.empty()) return asset;
        const std::filesystem::path relative = resolveAssetPath(from_, asset).lexically_relative(toDir_);
        return relative.empty() ? resolveAssetPath(from_, asset).string() : "./" + relative.string();
    }
    usda::Value value(const usda::Value& v) const {
        if (v.isNone()) return v;
        if (v.type() == usda::types::Asset)
            return usda::Value::make<usda::types::Asset>(path(v.get<usda::types::Asset>("asset")), v.location());
        if (v.type() != usda::types::AssetArray) return v;
        std::vector<std::string> paths = v.get<usda::types::AssetArray>("asset[]");
        for (std::string& p : paths) p = path(p);
        return usda::Value::make<usda::types::AssetArray>(std::move(paths), v.location());
    }
    void prim(usda::Prim& prim) const {
        for (auto* list : {&prim.references.explicitItems, &prim.references.prepended, &prim.references.appended})
            for (usda::Reference& r : *list) r.assetPath = path(r.assetPath);
        for (usda::Property& property : prim.properties) {
            auto* attribute = std::get_if<usda::Attribute>(&property);
            if (!attribute) continue;
            if (attribute->value) attribute->value = value(*attribute->value);
            for (usda::TimeSample& sample : attribute->timeSamples) sample.value = value(sample.value);
        }
        prims(prim.children);
    }

    std::filesystem::path from_, toDir_;
    bool needed_;
};

// `strong` over `weak`, as USD composes list ops across layers.
template <class T>
usda::ListOp<T> composeListOps(const usda::ListOp<T>& strong, const usda::ListOp<T>& weak) {
    if (strong.isExplicit || !weak.authored()) return strong;
    if (!strong.authored()) return weak;
    std::vector<T> items = strong.prepended;
    for (const T& item : weak.composed()) {
        const auto in = [&](const std::vector<T>& list) { return std::find(list.begin(), list.end(), item) != list.end(); };
        if (!in(strong.prepended) && !in(strong.appended)) items.push_back(item);
    }
    items.insert(items.end(), strong.appended.begin(), strong.appended.end());
    usda::ListOp<T> result;
    result.isExplicit = true;
    result.explicitItems = std::move(items);
    return result;
}

usda::Property* findProperty(usda::Prim& prim, const std::string& name) {
    for (usda::Property& p : prim.properties)
        if (usda::propertyName(p) == name) return &p;
    return nullptr;
}

void mergeDictionary(usda::Dictionary& strong, const usda::Dictionary& weak) {
    for (const usda::DictionaryEntry& entry : weak.entries()) strong.insert(entry.key, entry.value);
}

void composeProperty(usda::Property& strong, const usda::Property& weak) {
    auto* s = std::get_if<usda::Attribute>(&strong);
    const auto* w = std::get_if<usda::Attribute>(&weak);
    if (!s || !w) return;  // a relationship, or two kinds of property: the strongest stands
    mergeDictionary(s->metadata, w->metadata);
    if (!s->value && s->timeSamples.empty()) {
        s->value = w->value;
        s->timeSamples = w->timeSamples;
    }
}

void composePrims(std::vector<usda::Prim>& strong, const std::vector<usda::Prim>& weak);

void composePrim(usda::Prim& strong, const usda::Prim& weak) {
    if (strong.specifier == usda::Specifier::Over) strong.specifier = weak.specifier;
    if (strong.typeName.empty()) strong.typeName = weak.typeName;
    mergeDictionary(strong.metadata, weak.metadata);
    strong.apiSchemas = composeListOps(strong.apiSchemas, weak.apiSchemas);
    strong.references = composeListOps(strong.references, weak.references);
    if (!strong.inherits) strong.inherits = weak.inherits;
    for (const usda::Property& property : weak.properties) {
        if (usda::Property* mine = findProperty(strong, usda::propertyName(property)))
            composeProperty(*mine, property);
        else
            strong.properties.push_back(property);
    }
    composePrims(strong.children, weak.children);
}

void composePrims(std::vector<usda::Prim>& strong, const std::vector<usda::Prim>& weak) {
    for (const usda::Prim& prim : weak) {
        const auto mine = std::find_if(strong.begin(), strong.end(), [&](const usda::Prim& p) { return p.name == prim.name; });
        if (mine == strong.end())
            strong.push_back(prim);
        else
            composePrim(*mine, prim);
    }
}

}  // namespace

usda::Layer composeLayerStack(const std::filesystem::path& file) {
    std::vector<StackLayer> stack;
    std::vector<std::filesystem::path> chain;
    readStack(file, chain, stack);
    usda::Layer composed = std::move(stack.front().layer);
    composed.subLayers.clear();  // composed below
    for (std::size_t i = 1; i < stack.size(); ++i) {
        Reanchor(stack[i].file, file).prims(stack[i].layer.rootPrims);
        composePrims(composed.rootPrims, stack[i].layer.rootPrims);
    }
    return composed;
}

}  // namespace opal::scene
