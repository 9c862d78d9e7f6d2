// The USDA value model: a typed value (scalar, array, dictionary or None) with the
// place it was read from, and the dictionary (customData, customLayerData, ...) that
// holds named values. Accessors check the type and throw UsdaError naming the
// location, what was being read, the type found and the type expected.
#pragma once

#include "schema/usd/usda_location.h"
#include "schema/usd/usda_type.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace opal::usda {

class Value;
struct DictionaryEntry;

// Named values kept sorted by key (the order USD writes them in), keys unique.
class Dictionary {
public:
    Dictionary();
    Dictionary(const Dictionary&);
    Dictionary(Dictionary&&) noexcept;
    Dictionary& operator=(const Dictionary&);
    Dictionary& operator=(Dictionary&&) noexcept;
    ~Dictionary();

    const Value* find(std::string_view key) const;
    bool contains(std::string_view key) const { return find(key) != nullptr; }
    // Inserts or replaces.
    void set(std::string key, Value value);
    // Inserts; returns false (and changes nothing) when the key is already present.
    bool insert(std::string key, Value value);
    bool erase(std::string_view key);

    const std::vector<DictionaryEntry>& entries() const { return entries_; }
    // Out of line: DictionaryEntry is incomplete here, and clang instantiates inline uses.
    bool empty() const;
    std::size_t size() const;

    friend bool operator==(const Dictionary& a, const Dictionary& b);

private:
    std::vector<DictionaryEntry>::iterator lowerBound(std::string_view key);
    std::vector<DictionaryEntry> entries_;
};

class Value {
public:
    using Data = std::variant<
        std::monostate, bool, std::int32_t, std::uint32_t, std::int64_t, std::uint64_t, float,
        double, std::string, Vec2i, Vec3i, Vec4i, Vec2f, Vec3f, Vec4f, Vec2d, Vec3d, Vec4d,
        Matrix4d, Dictionary, std::vector<bool>, std::vector<std::int32_t>,
        std::vector<std::uint32_t>, std::vector<std::int64_t>, std::vector<std::uint64_t>,
        std::vector<float>, std::vector<double>, std::vector<std::string>, std::vector<Vec2i>,
        std::vector<Vec3i>, std::vector<Vec4i>, std::vector<Vec2f>, std::vector<Vec3f>,
        std::vector<Vec4f>, std::vector<Vec2d>, std::vector<Vec3d>, std::vector<Vec4d>,
        std::vector<Matrix4d>>;

    template <ValueType T>
    static Value make(StorageOf<T> data, SourceLocation where = {}) {
        return Value(T, Data(std::in_place_type<StorageOf<T>>, std::move(data)), std::move(where));
    }
    // USDA's `None`: an attribute default that blocks weaker opinions.
    static Value none(ValueType type, SourceLocation where = {}) {
        return Value(type, Data(), std::move(where));
    }

    // Shorthands for the common metadata kinds.
    static Value string(std::string s) { return make<types::String>(std::move(s)); }
    static Value token(std::string s) { return make<types::Token>(std::move(s)); }
    static Value asset(std::string s) { return make<types::Asset>(std::move(s)); }
    static Value dictionary(Dictionary d) { return make<types::Dictionary>(std::move(d)); }

    ValueType type() const { return type_; }
    bool isNone() const { return std::holds_alternative<std::monostate>(data_); }
    template <ValueType T>
    bool is() const { return type_ == T && !isNone(); }
    const SourceLocation& location() const { return where_; }
    const Data& data() const { return data_; }

    // The stored data if this value has type T; otherwise throws UsdaError
    // "<where>: <what> has type float3[], expected point3f[]" (`what` names the
    // value for the message, e.g. "attribute 'points'" or "customData 'libraryName'").
    template <ValueType T>
    const StorageOf<T>& get(std::string_view what) const {
        if (!is<T>()) {
            throwWrongType(what, T);
        }
        return std::get<StorageOf<T>>(data_);
    }

    friend bool operator==(const Value&, const Value&) = default;

    [[noreturn]] void throwWrongType(std::string_view what, ValueType expected) const;

private:
    Value(ValueType type, Data data, SourceLocation where)
        : type_(type), data_(std::move(data)), where_(std::move(where)) {}

    ValueType type_;
    Data data_;
    SourceLocation where_;
};

struct DictionaryEntry {
    std::string key;
    Value value;

    friend bool operator==(const DictionaryEntry&, const DictionaryEntry&) = default;
};

}  // namespace opal::usda
