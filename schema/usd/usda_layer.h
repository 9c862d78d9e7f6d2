// The USDA layer model: a Layer (header metadata, root prims), Prims (specifier, type,
// name, metadata, list-edited apiSchemas and references, properties and children in
// order), Attributes and Relationships. Plain aggregates: readers fill them, writers
// (opal-bake, scene tools) build them; lookup helpers throw UsdaError with the
// location of the prim or property they were asked about.
#pragma once

#include "schema/usd/usda_error.h"
#include "schema/usd/usda_location.h"
#include "schema/usd/usda_type.h"
#include "schema/usd/usda_value.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace opal::usda {

enum class Specifier { Def, Over, Class };
std::string_view specifierKeyword(Specifier s);  // "def", "over", "class"

// An SdfListOp restricted to what Opal accepts: either an explicit list
// (`apiSchemas = [...]`, `= None` for an explicit empty list) or prepend/append edits.
template <class T>
struct ListOp {
    bool isExplicit = false;
    std::vector<T> explicitItems{};
    std::vector<T> prepended{};
    std::vector<T> appended{};

    bool authored() const { return isExplicit || !prepended.empty() || !appended.empty(); }
    // The list this op yields when applied over an empty weaker list.
    std::vector<T> composed() const {
        std::vector<T> items = prepended;
        items.insert(items.end(), explicitItems.begin(), explicitItems.end());
        items.insert(items.end(), appended.begin(), appended.end());
        return items;
    }
    friend bool operator==(const ListOp&, const ListOp&) = default;
};

// `@./wax.usda@</Asset>`: an external reference (assetPath set, primPath optional,
// empty meaning the referenced layer's defaultPrim) or an internal one (`</Prim>`).
struct Reference {
    std::string assetPath{};
    std::string primPath{};
    SourceLocation location{};

    friend bool operator==(const Reference&, const Reference&) = default;
};

// One authored time sample of an attribute (`x.timeSamples = { 12: 2.5 }`): the time code
// and the value there, which may be None (blocked from that time on).
struct TimeSample {
    double time = 0.0;
    Value value;

    friend bool operator==(const TimeSample&, const TimeSample&) = default;
};

struct Attribute {
    std::string name{};  // namespaced: "points", "opal:sigmaA", "xformOp:translate"
    ValueType type{};
    bool custom = false;
    bool uniform = false;
    std::optional<Value> value{};  // the default (`= ...`); may be None
    // `.timeSamples`, sorted by time, times unique. An attribute with samples is read at a
    // time code only (time_samples.h); the typed readers below refuse it.
    std::vector<TimeSample> timeSamples{};
    std::string comment{};         // bare string at the top of the metadata block
    Dictionary metadata{};         // doc, interpolation, elementSize, customData, ...
    SourceLocation location{};     // of the declaration's first token

    bool hasValue() const { return value && !value->isNone(); }
    // The value if it is authored, not None, not time-sampled and of type T; otherwise
    // throws "<where>: attribute 'points' has type float3[], expected point3f[]".
    template <ValueType T>
    const StorageOf<T>& get() const {
        requireType(T);
        return std::get<StorageOf<T>>(value->data());
    }
    void requireType(ValueType expected) const;

    friend bool operator==(const Attribute&, const Attribute&) = default;
};

struct Relationship {
    std::string name{};  // "material:binding"
    bool custom = false;
    std::optional<std::vector<std::string>> targets{};  // paths, without < >; nullopt: declared only
    std::string comment{};
    Dictionary metadata{};
    SourceLocation location{};

    // The one target; throws UsdaError unless exactly one is authored.
    const std::string& target() const;

    friend bool operator==(const Relationship&, const Relationship&) = default;
};

using Property = std::variant<Attribute, Relationship>;
const std::string& propertyName(const Property& p);
// "float3 or double3".
std::string typeNames(std::span<const ValueType> types);
const SourceLocation& propertyLocation(const Property& p);

struct Prim {
    Specifier specifier = Specifier::Def;
    std::string typeName{};  // empty: typeless (`def "Root"`, `class "OpalSubsurfaceAPI"`)
    std::string name{};
    std::string comment{};
    Dictionary metadata{};  // doc, kind, customData, active, hidden, instanceable, ...
    ListOp<std::string> apiSchemas{};
    ListOp<Reference> references{};
    std::optional<std::string> inherits{};  // single path; class prims (schema files) only
    std::vector<Property> properties{};
    std::vector<Prim> children{};
    SourceLocation location{};  // of the specifier keyword

    const Attribute* findAttribute(std::string_view name) const;
    const Relationship* findRelationship(std::string_view name) const;
    const Prim* findChild(std::string_view name) const;
    // Throwing lookups: "<where>: prim 'Asset' has no attribute 'points'".
    const Attribute& attribute(std::string_view name) const;

    // Opal's one reader of typed attribute values (the bake's import, the asset layer and
    // the scene reader all read through these).
    // The attribute `name` when it holds a value; nullptr when the prim has no property of
    // that name, declares the attribute without a value or blocks it (None). Throws
    // UsdaError at the property when it is declared with none of the `accepted` types,
    // "<context>: attribute 'points' has type float3[], expected point3f[]", or is a
    // relationship; `context` names the prim as the caller's messages do ("Mesh </Cube>"),
    // and an empty one leaves "<context>: " out.
    const Attribute* findValue(std::string_view name, std::span<const ValueType> accepted,
                               std::string_view context = {}) const;
    // The same for one type: the value itself, nullptr when there is none.
    template <ValueType T>
    const StorageOf<T>* findValue(std::string_view name, std::string_view context = {}) const {
        const ValueType accepted[] = {T};
        const Attribute* a = findValue(name, accepted, context);
        return a ? &std::get<StorageOf<T>>(a->value->data()) : nullptr;
    }
    // The value of an attribute the prim must author; throws as attribute() when it does
    // not, and as Attribute::get otherwise.
    template <ValueType T>
    const StorageOf<T>& requiredValue(std::string_view name) const {
        return attribute(name).get<T>();
    }
    const Relationship& relationship(std::string_view name) const;
    const Prim& child(std::string_view name) const;

    bool hasApiSchema(std::string_view schema) const;
    std::string kind() const;  // "" when not authored
    std::string doc() const;
    const Dictionary* customData() const;

    // Builders; each throws opal::Error when a property or child of that name exists.
    Attribute& addAttribute(std::string name, Value value, bool uniform = false);
    Relationship& addRelationship(std::string name, std::vector<std::string> targets);
    Prim& addChild(Prim child);

    friend bool operator==(const Prim&, const Prim&) = default;
};

struct Layer {
    std::string comment{};  // bare string at the top of the header metadata
    Dictionary metadata{};  // doc, defaultPrim, upAxis, metersPerUnit, customLayerData, ...
    std::vector<std::string> subLayers{};  // asset paths; composed by the scene reader only (examples/scene/layer_stack.h)
    std::vector<Prim> rootPrims{};
    SourceLocation location{};  // the file (line 0)

    // "/World/Candle"; nullptr when there is none.
    const Prim* findPrim(std::string_view path) const;
    const Prim& prim(std::string_view path) const;  // throws UsdaError naming the path

    std::string doc() const;
    std::string defaultPrim() const;
    std::string upAxis() const;
    std::optional<double> metersPerUnit() const;
    const Dictionary* customLayerData() const;

    Prim& addRootPrim(Prim prim);  // throws opal::Error on a duplicate name

    friend bool operator==(const Layer&, const Layer&) = default;
};

}  // namespace opal::usda
