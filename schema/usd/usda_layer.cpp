#include "schema/usd/usda_layer.h"

#include "schema/usd/usda_error.h"

#include <algorithm>

namespace opal::usda {
namespace {

std::string quoted(std::string_view s) {
    std::string out(1, '\'');
    out += s;
    out += '\'';
    return out;
}

std::string stringMetadata(const Dictionary& metadata, std::string_view key) {
    const Value* v = metadata.find(key);
    return v ? v->get<types::String>("metadata " + quoted(key)) : std::string();
}

std::string tokenMetadata(const Dictionary& metadata, std::string_view key) {
    const Value* v = metadata.find(key);
    return v ? v->get<types::Token>("metadata " + quoted(key)) : std::string();
}

const Dictionary* dictionaryMetadata(const Dictionary& metadata, std::string_view key) {
    const Value* v = metadata.find(key);
    return v ? &v->get<types::Dictionary>("metadata " + quoted(key)) : nullptr;
}

template <class T>
const T* findProperty(const std::vector<Property>& properties, std::string_view name) {
    for (const Property& p : properties) {
        if (const T* typed = std::get_if<T>(&p); typed && typed->name == name) {
            return typed;
        }
    }
    return nullptr;
}

bool hasProperty(const std::vector<Property>& properties, std::string_view name) {
    return std::any_of(properties.begin(), properties.end(),
                       [&](const Property& p) { return propertyName(p) == name; });
}

const Prim* findByName(const std::vector<Prim>& prims, std::string_view name) {
    auto it = std::find_if(prims.begin(), prims.end(), [&](const Prim& p) { return p.name == name; });
    return it != prims.end() ? &*it : nullptr;
}

// A value read without a time cannot stand for an animated attribute: refuse rather than
// silently take the default (scenes evaluate attributes at their time, time_samples.h).
void requireUntimed(const Attribute& a, std::string_view what) {
    if (!a.timeSamples.empty())
        throw UsdaError(a.timeSamples.front().value.location(),
                        std::string(what) + " has timeSamples; Opal reads time-sampled attributes only in scenes, "
                                            "at the scene time");
}

}  // namespace

std::string_view specifierKeyword(Specifier s) {
    switch (s) {
        case Specifier::Def: return "def";
        case Specifier::Over: return "over";
        case Specifier::Class: return "class";
    }
    return "def";
}

void Attribute::requireType(ValueType expected) const {
    std::string what = "attribute " + quoted(name);
    requireUntimed(*this, what);
    if (!value) {
        throw UsdaError(location, what + " has no value, expected " + typeName(expected));
    }
    if (type != expected || value->type() != expected) {
        throw UsdaError(location, what + " has type " + typeName(type) + ", expected " + typeName(expected));
    }
    if (value->isNone()) {
        throw UsdaError(location, what + " is None (blocked), expected a " + typeName(expected));
    }
}

const std::string& Relationship::target() const {
    if (!targets || targets->size() != 1) {
        std::size_t n = targets ? targets->size() : 0;
        throw UsdaError(location, "relationship " + quoted(name) + " has " + std::to_string(n) +
                                      " targets, expected exactly one");
    }
    return targets->front();
}

const std::string& propertyName(const Property& p) {
    return std::visit([](const auto& typed) -> const std::string& { return typed.name; }, p);
}

std::string typeNames(std::span<const ValueType> types) {
    std::string text;
    for (ValueType t : types) text += (text.empty() ? "" : " or ") + typeName(t);
    return text;
}

const SourceLocation& propertyLocation(const Property& p) {
    return std::visit([](const auto& typed) -> const SourceLocation& { return typed.location; }, p);
}

const Attribute* Prim::findAttribute(std::string_view n) const { return findProperty<Attribute>(properties, n); }

const Relationship* Prim::findRelationship(std::string_view n) const {
    return findProperty<Relationship>(properties, n);
}

const Prim* Prim::findChild(std::string_view n) const { return findByName(children, n); }

const Attribute& Prim::attribute(std::string_view n) const {
    if (const Attribute* a = findAttribute(n)) {
        return *a;
    }
    throw UsdaError(location, "prim " + quoted(name) + " has no attribute " + quoted(n));
}

const Attribute* Prim::findValue(std::string_view n, std::span<const ValueType> accepted,
                                 std::string_view context) const {
    const auto property = std::find_if(properties.begin(), properties.end(),
                                       [&](const Property& p) { return propertyName(p) == n; });
    if (property == properties.end()) return nullptr;
    const std::string prefix = context.empty() ? std::string() : std::string(context) + ": ";
    const auto* a = std::get_if<Attribute>(&*property);
    if (!a) {
        throw UsdaError(propertyLocation(*property),
                        prefix + quoted(n) + " is a relationship, expected an attribute of type " + usda::typeNames(accepted));
    }
    const auto acceptable = [&](ValueType t) { return std::find(accepted.begin(), accepted.end(), t) != accepted.end(); };
    // A built layer could hold a value of another type than declared: both are checked.
    const ValueType actual = !acceptable(a->type) || !a->hasValue() ? a->type : a->value->type();
    if (!acceptable(actual)) {
        throw UsdaError(a->location, prefix + "attribute " + quoted(n) + " has type " + usda::typeName(actual) +
                                         ", expected " + typeNames(accepted));
    }
    requireUntimed(*a, prefix + "attribute " + quoted(n));
    return a->hasValue() ? a : nullptr;
}

const Relationship& Prim::relationship(std::string_view n) const {
    if (const Relationship* r = findRelationship(n)) {
        return *r;
    }
    throw UsdaError(location, "prim " + quoted(name) + " has no relationship " + quoted(n));
}

const Prim& Prim::child(std::string_view n) const {
    if (const Prim* c = findChild(n)) {
        return *c;
    }
    throw UsdaError(location, "prim " + quoted(name) + " has no child prim " + quoted(n));
}

bool Prim::hasApiSchema(std::string_view schema) const {
    std::vector<std::string> applied = apiSchemas.composed();
    return std::find(applied.begin(), applied.end(), schema) != applied.end();
}

std::string Prim::kind() const { return tokenMetadata(metadata, "kind"); }
std::string Prim::doc() const { return stringMetadata(metadata, "doc"); }
const Dictionary* Prim::customData() const { return dictionaryMetadata(metadata, "customData"); }

Attribute& Prim::addAttribute(std::string n, Value v, bool uniform) {
    if (hasProperty(properties, n)) {
        throw opal::Error("prim '" + name + "' already has a property '" + n + "'");
    }
    Attribute attr;
    attr.name = std::move(n);
    attr.type = v.type();
    attr.uniform = uniform;
    attr.value = std::move(v);
    properties.emplace_back(std::move(attr));
    return std::get<Attribute>(properties.back());
}

Relationship& Prim::addRelationship(std::string n, std::vector<std::string> t) {
    if (hasProperty(properties, n)) {
        throw opal::Error("prim '" + name + "' already has a property '" + n + "'");
    }
    Relationship rel;
    rel.name = std::move(n);
    rel.targets = std::move(t);
    properties.emplace_back(std::move(rel));
    return std::get<Relationship>(properties.back());
}

Prim& Prim::addChild(Prim c) {
    if (findChild(c.name)) {
        throw opal::Error("prim '" + name + "' already has a child '" + c.name + "'");
    }
    children.push_back(std::move(c));
    return children.back();
}

const Prim* Layer::findPrim(std::string_view path) const {
    if (!path.starts_with('/')) {
        return nullptr;
    }
    const std::vector<Prim>* level = &rootPrims;
    const Prim* found = nullptr;
    do {
        path.remove_prefix(1);  // the '/'
        std::size_t slash = std::min(path.find('/'), path.size());
        found = slash > 0 ? findByName(*level, path.substr(0, slash)) : nullptr;
        if (!found) {
            return nullptr;
        }
        level = &found->children;
        path.remove_prefix(slash);
    } while (!path.empty());
    return found;
}

const Prim& Layer::prim(std::string_view path) const {
    if (const Prim* p = findPrim(path)) {
        return *p;
    }
    throw UsdaError(location, "no prim at path " + quoted(path));
}

std::string Layer::doc() const { return stringMetadata(metadata, "doc"); }
std::string Layer::defaultPrim() const { return tokenMetadata(metadata, "defaultPrim"); }
std::string Layer::upAxis() const { return tokenMetadata(metadata, "upAxis"); }

std::optional<double> Layer::metersPerUnit() const {
    const Value* v = metadata.find("metersPerUnit");
    return v ? std::optional<double>(v->get<types::Double>("metadata 'metersPerUnit'")) : std::nullopt;
}

const Dictionary* Layer::customLayerData() const { return dictionaryMetadata(metadata, "customLayerData"); }

Prim& Layer::addRootPrim(Prim p) {
    if (findByName(rootPrims, p.name)) {
        throw opal::Error("layer already has a root prim '" + p.name + "'");
    }
    rootPrims.push_back(std::move(p));
    return rootPrims.back();
}

}  // namespace opal::usda
