#include "schema/usd/usda_value.h"

#include "schema/usd/usda_error.h"

#include <algorithm>

namespace opal::usda {

Dictionary::Dictionary() = default;
Dictionary::Dictionary(const Dictionary&) = default;
Dictionary::Dictionary(Dictionary&&) noexcept = default;
Dictionary& Dictionary::operator=(const Dictionary&) = default;
Dictionary& Dictionary::operator=(Dictionary&&) noexcept = default;
Dictionary::~Dictionary() = default;

bool Dictionary::empty() const { return entries_.empty(); }
std::size_t Dictionary::size() const { return entries_.size(); }

std::vector<DictionaryEntry>::iterator Dictionary::lowerBound(std::string_view key) {
    return std::lower_bound(entries_.begin(), entries_.end(), key,
                            [](const DictionaryEntry& e, std::string_view k) { return e.key < k; });
}

const Value* Dictionary::find(std::string_view key) const {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                               [](const DictionaryEntry& e, std::string_view k) { return e.key < k; });
    return it != entries_.end() && it->key == key ? &it->value : nullptr;
}

void Dictionary::set(std::string key, Value value) {
    auto it = lowerBound(key);
    if (it != entries_.end() && it->key == key) {
        it->value = std::move(value);
        return;
    }
    entries_.insert(it, DictionaryEntry{std::move(key), std::move(value)});
}

bool Dictionary::insert(std::string key, Value value) {
    auto it = lowerBound(key);
    if (it != entries_.end() && it->key == key) {
        return false;
    }
    entries_.insert(it, DictionaryEntry{std::move(key), std::move(value)});
    return true;
}

bool Dictionary::erase(std::string_view key) {
    auto it = lowerBound(key);
    if (it == entries_.end() || it->key != key) {
        return false;
    }
    entries_.erase(it);
    return true;
}

bool operator==(const Dictionary& a, const Dictionary& b) { return a.entries_ == b.entries_; }

void Value::throwWrongType(std::string_view what, ValueType expected) const {
    std::string found = isNone() ? " is None (blocked)" : " has type " + typeName(type_);
    throw UsdaError(where_, std::string(what) + found + ", expected " + typeName(expected));
}

}  // namespace opal::usda
