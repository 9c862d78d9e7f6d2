#include "examples/scene/prim_reader.h"

#include "examples/scene/asset_path.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace opal::scene {

std::string Bounds::describe() const {
    const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
    if (hasMin && hasMax)
        return std::string("in ") + (openMin ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) + (openMax ? ")" : "]");
    if (hasMin) return (openMin ? "> " : ">= ") + formatNumber(min);
    if (hasMax) return (openMax ? "< " : "<= ") + formatNumber(max);
    return "finite";
}

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string quotedName(std::string_view name) {
    std::string text(1, '\'');
    text.append(name);
    text += '\'';
    return text;
}

PrimReader::PrimReader(const usda::Prim& prim, hd::SdfPath path) : prim_(prim), path_(std::move(path)) {}

std::string PrimReader::describe() const {
    return (prim_.typeName.empty() ? std::string("prim") : prim_.typeName) + " <" + path_ + ">";
}

const usda::Property* PrimReader::findProperty(std::string_view name) const {
    const auto it = std::find_if(prim_.properties.begin(), prim_.properties.end(),
                                 [&](const usda::Property& p) { return usda::propertyName(p) == name; });
    return it == prim_.properties.end() ? nullptr : &*it;
}

const usda::Attribute* PrimReader::find(std::string_view name, std::span<const usda::ValueType> accepted) {
    understood_.emplace(name);
    return prim_.findValue(name, accepted, describe());
}

std::optional<double> PrimReader::real(std::string_view name, usda::ValueType declared, Bounds bounds) {
    const usda::Attribute* attribute = find(name, {declared});
    if (!attribute) return std::nullopt;
    const usda::Value::Data& data = attribute->value->data();
    const float* f = std::get_if<float>(&data);
    const double value = f ? double(*f) : std::get<double>(data);
    if (!std::isfinite(value) || !bounds.contains(value))
        failAt(*attribute, "is " + formatNumber(value) + ", expected a value " + bounds.describe());
    return value;
}

std::optional<std::filesystem::path> PrimReader::existingFile(std::string_view name,
                                                             const std::filesystem::path& layerFile) {
    const usda::Attribute* attribute = find(name, {usda::types::Asset});
    if (!attribute) return std::nullopt;
    const std::string& asset = std::get<std::string>(attribute->value->data());
    const std::filesystem::path file = resolveAssetPath(layerFile, asset);
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
        failAt(*attribute, "names @" + asset + "@, which does not exist (resolved to " + file.string() + ")");
    return file;
}

std::optional<Rgb> PrimReader::color(std::string_view name, Bounds bounds) {
    const usda::Attribute* attribute = find(name, {usda::types::Color3f});
    if (!attribute) return std::nullopt;
    const usda::Vec3f& c = std::get<usda::Vec3f>(attribute->value->data());
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i]) || !bounds.contains(c[i]))
            failAt(*attribute, "is (" + formatNumber(c[0]) + ", " + formatNumber(c[1]) + ", " + formatNumber(c[2]) +
                                   "), expected every component " + bounds.describe());
    return Rgb(c[0], c[1], c[2]);
}

const usda::Relationship* PrimReader::relationship(std::string_view name) {
    understood_.emplace(name);
    const usda::Property* property = findProperty(name);
    if (!property) return nullptr;
    const auto* relationship = std::get_if<usda::Relationship>(property);
    if (!relationship) fail(usda::propertyLocation(*property), quotedName(name) + " is an attribute, expected a relationship");
    return relationship;
}

void PrimReader::ignore(std::string_view name) { understood_.emplace(name); }

std::vector<const usda::Property*> PrimReader::withPrefix(std::string_view prefix) const {
    std::vector<const usda::Property*> found;
    for (const usda::Property& p : prim_.properties)
        if (usda::propertyName(p).starts_with(prefix)) found.push_back(&p);
    return found;
}

void PrimReader::finish() const {
    for (const usda::Property& p : prim_.properties) {
        const std::string& name = usda::propertyName(p);
        if (understood_.count(name)) continue;
        std::string accepted;
        for (const std::string& known : understood_) accepted += (accepted.empty() ? "" : ", ") + known;
        const char* kind = std::holds_alternative<usda::Relationship>(p) ? "relationship " : "attribute ";
        fail(usda::propertyLocation(p), "unknown " + std::string(kind) + quotedName(name) + " (" +
                                            (prim_.typeName.empty() ? std::string("this prim") : prim_.typeName) +
                                            " accepts " + (accepted.empty() ? std::string("none") : accepted) +
                                            "; see examples/SCENES.md)");
    }
}

void PrimReader::fail(const usda::SourceLocation& where, const std::string& message) const {
    throw usda::UsdaError(where, describe() + ": " + message);
}

void PrimReader::failAt(const usda::Attribute& attribute, const std::string& problem) const {
    fail(attribute.location, "attribute " + quotedName(attribute.name) + " " + problem);
}

void PrimReader::failAt(const usda::Relationship& relationship, const std::string& problem) const {
    fail(relationship.location, "relationship " + quotedName(relationship.name) + " " + problem);
}

}  // namespace opal::scene
