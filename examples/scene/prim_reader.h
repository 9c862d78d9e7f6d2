// Strict, typed reading of one scene prim's properties (examples/SCENES.md). Every read
// checks the declared type and records the property as understood; finish() then rejects
// whatever the prim authored that no read asked for, so a misspelt or unsupported
// attribute is an error with its file:line:column, never silently ignored. Messages start
// with the location and name the prim: "scene.usda:9:5: SphereLight </World/Key>: ...".
#pragma once

#include "delegate/hd/types.h"
#include "schema/scatter/rgb.h"
#include "schema/usd/usda_error.h"
#include "schema/usd/usda_layer.h"

#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>

namespace opal::scene {

// The interval a numeric attribute must lie in (each color component too); closed unless
// an end is marked open.
struct Bounds {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool openMin = false, openMax = false;

    static Bounds atLeast(double min) { return {min}; }
    static Bounds positive() { return {0.0, std::numeric_limits<double>::infinity(), true}; }
    static Bounds closed(double min, double max) { return {min, max}; }

    bool contains(double v) const {
        return (openMin ? v > min : v >= min) && (openMax ? v < max : v <= max);
    }
    std::string describe() const;  // ">= 0", "> 0", "in [0, 180]", "in (0, 1)", "finite"
};

class PrimReader {
public:
    PrimReader(const usda::Prim& prim, hd::SdfPath path);

    const usda::Prim& prim() const { return prim_; }
    const hd::SdfPath& path() const { return path_; }
    // "SphereLight </World/Key>" ("prim </World>" for a typeless prim).
    std::string describe() const;

    // The attribute `name` when it holds a value (authored, not None); nullptr when it is
    // absent, only declared or blocked. Throws UsdaError at the attribute when it is
    // declared with none of `accepted` types, or when `name` is a relationship.
    const usda::Attribute* find(std::string_view name, std::span<const usda::ValueType> accepted);
    const usda::Attribute* find(std::string_view name, std::initializer_list<usda::ValueType> accepted) {
        return find(name, std::span<const usda::ValueType>(accepted.begin(), accepted.size()));
    }
    template <usda::ValueType T>
    std::optional<usda::StorageOf<T>> get(std::string_view name) {
        const usda::Attribute* attribute = find(name, {T});
        if (!attribute) return std::nullopt;
        return std::get<usda::StorageOf<T>>(attribute->value->data());
    }
    // A float or double attribute (as the schema declares it) as a double; throws at the
    // attribute for a non-finite value or one outside `bounds`.
    std::optional<double> real(std::string_view name, usda::ValueType declared, Bounds bounds = {});
    // An asset attribute naming a file, resolved against `layerFile` (asset_path.h);
    // throws at the attribute when no such file exists.
    std::optional<std::filesystem::path> existingFile(std::string_view name, const std::filesystem::path& layerFile);
    // A color3f attribute; throws for a component that is non-finite or outside `bounds`.
    std::optional<Rgb> color(std::string_view name, Bounds bounds = {});

    // The relationship `name`, nullptr when absent. Throws when `name` is an attribute.
    const usda::Relationship* relationship(std::string_view name);

    // Standard attributes Opal accepts only at their schema fallback: throws at the
    // attribute, saying `unsupported`, when it holds another value.
    template <usda::ValueType T>
    void requireFallback(std::string_view name, const usda::StorageOf<T>& fallback, std::string_view unsupported) {
        const usda::Attribute* attribute = find(name, {T});
        if (attribute && std::get<usda::StorageOf<T>>(attribute->value->data()) != fallback)
            failAt(*attribute, "differs from its fallback value, the only one Opal supports (" +
                                   std::string(unsupported) + ")");
    }

    // Marks `name` as understood whatever it holds: standard attributes Opal ignores.
    void ignore(std::string_view name);
    // Every authored property whose name starts with `prefix` (e.g. "xformOp:"), in order.
    std::vector<const usda::Property*> withPrefix(std::string_view prefix) const;

    // Throws UsdaError at the first property no read asked for, listing what this prim
    // type accepts.
    void finish() const;

    // Throw UsdaError "<where>: <describe()>: <message>".
    [[noreturn]] void fail(const usda::SourceLocation& where, const std::string& message) const;
    [[noreturn]] void failAt(const usda::Attribute& attribute, const std::string& problem) const;
    [[noreturn]] void failAt(const usda::Relationship& relationship, const std::string& problem) const;

private:
    const usda::Property* findProperty(std::string_view name) const;

    const usda::Prim& prim_;
    hd::SdfPath path_;
    std::set<std::string, std::less<>> understood_;
};

// "'inputs:intensity'": how messages quote names.
std::string quotedName(std::string_view name);
// The shortest text that shows a value in a message: "0.5", "1e+06".
std::string formatNumber(double value);

}  // namespace opal::scene
