#include "schema/usd/usda_type.h"

#include <utility>

namespace opal::usda {
namespace {

constexpr std::pair<std::string_view, ScalarType> kScalarNames[] = {
    {"bool", ScalarType::Bool},         {"int", ScalarType::Int},
    {"uint", ScalarType::UInt},         {"int64", ScalarType::Int64},
    {"uint64", ScalarType::UInt64},     {"float", ScalarType::Float},
    {"double", ScalarType::Double},     {"string", ScalarType::String},
    {"token", ScalarType::Token},       {"asset", ScalarType::Asset},
    {"int2", ScalarType::Int2},         {"int3", ScalarType::Int3},
    {"int4", ScalarType::Int4},         {"float2", ScalarType::Float2},
    {"float3", ScalarType::Float3},     {"float4", ScalarType::Float4},
    {"double2", ScalarType::Double2},   {"double3", ScalarType::Double3},
    {"double4", ScalarType::Double4},   {"point3f", ScalarType::Point3f},
    {"point3d", ScalarType::Point3d},   {"normal3f", ScalarType::Normal3f},
    {"normal3d", ScalarType::Normal3d}, {"vector3f", ScalarType::Vector3f},
    {"vector3d", ScalarType::Vector3d}, {"color3f", ScalarType::Color3f},
    {"color3d", ScalarType::Color3d},   {"color4f", ScalarType::Color4f},
    {"color4d", ScalarType::Color4d},   {"texCoord2f", ScalarType::TexCoord2f},
    {"texCoord2d", ScalarType::TexCoord2d}, {"quatf", ScalarType::Quatf},
    {"quatd", ScalarType::Quatd},       {"matrix4d", ScalarType::Matrix4d},
    {"dictionary", ScalarType::Dictionary},
};

}  // namespace

std::string typeName(ValueType type) {
    for (const auto& [name, scalar] : kScalarNames) {
        if (scalar == type.scalar) {
            return std::string(name) + (type.isArray ? "[]" : "");
        }
    }
    return "?";
}

std::optional<ValueType> parseTypeName(std::string_view name) {
    bool isArray = name.ends_with("[]");
    if (isArray) {
        name.remove_suffix(2);
    }
    for (const auto& [candidate, scalar] : kScalarNames) {
        if (candidate == name) {
            if (scalar == ScalarType::Dictionary && isArray) {
                return std::nullopt;
            }
            return ValueType{scalar, isArray};
        }
    }
    return std::nullopt;
}

bool isAttributeType(ValueType type) { return type.scalar != ScalarType::Dictionary; }

}  // namespace opal::usda
