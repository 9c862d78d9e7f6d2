// USDA value type names (Sdf's "serialization names": float3, point3f[], token, ...)
// and the C++ type each one is stored as. Role types share storage with their plain
// form (point3f, normal3f, vector3f, color3f and float3 are all Vec3f) but keep their
// own name, so a reader that expects point3f[] can reject a float3[].
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace opal::usda {

class Dictionary;

using Vec2i = std::array<std::int32_t, 2>;
using Vec3i = std::array<std::int32_t, 3>;
using Vec4i = std::array<std::int32_t, 4>;
using Vec2f = std::array<float, 2>;
using Vec3f = std::array<float, 3>;
using Vec4f = std::array<float, 4>;
using Vec2d = std::array<double, 2>;
using Vec3d = std::array<double, 3>;
using Vec4d = std::array<double, 4>;
using Quatf = std::array<float, 4>;  // (real, i, j, k), in the order USDA writes them
using Quatd = std::array<double, 4>;
using Matrix4d = std::array<Vec4d, 4>;  // rows as written: row-vector convention, translation in row 3

enum class ScalarType : std::uint8_t {
    Bool, Int, UInt, Int64, UInt64, Float, Double,
    String, Token, Asset,
    Int2, Int3, Int4, Float2, Float3, Float4, Double2, Double3, Double4,
    Point3f, Point3d, Normal3f, Normal3d, Vector3f, Vector3d,
    Color3f, Color3d, Color4f, Color4d, TexCoord2f, TexCoord2d, Quatf, Quatd,
    Matrix4d,
    Dictionary,  // only in metadata and dictionaries, never as an attribute type
};

// A scalar type or an array of it. Usable as a template argument: get<types::Int>().
struct ValueType {
    ScalarType scalar = ScalarType::Bool;
    bool isArray = false;

    friend constexpr bool operator==(ValueType, ValueType) = default;
};

// "point3f[]" etc.; the inverse returns nullopt for names outside Opal's subset.
std::string typeName(ValueType type);
std::optional<ValueType> parseTypeName(std::string_view name);

// What attributes may be declared with (everything but dictionary).
bool isAttributeType(ValueType type);

namespace types {
inline constexpr ValueType Bool{ScalarType::Bool}, BoolArray{ScalarType::Bool, true};
inline constexpr ValueType Int{ScalarType::Int}, IntArray{ScalarType::Int, true};
inline constexpr ValueType UInt{ScalarType::UInt}, UIntArray{ScalarType::UInt, true};
inline constexpr ValueType Int64{ScalarType::Int64}, Int64Array{ScalarType::Int64, true};
inline constexpr ValueType UInt64{ScalarType::UInt64}, UInt64Array{ScalarType::UInt64, true};
inline constexpr ValueType Float{ScalarType::Float}, FloatArray{ScalarType::Float, true};
inline constexpr ValueType Double{ScalarType::Double}, DoubleArray{ScalarType::Double, true};
inline constexpr ValueType String{ScalarType::String}, StringArray{ScalarType::String, true};
inline constexpr ValueType Token{ScalarType::Token}, TokenArray{ScalarType::Token, true};
inline constexpr ValueType Asset{ScalarType::Asset}, AssetArray{ScalarType::Asset, true};
inline constexpr ValueType Int2{ScalarType::Int2}, Int2Array{ScalarType::Int2, true};
inline constexpr ValueType Int3{ScalarType::Int3}, Int3Array{ScalarType::Int3, true};
inline constexpr ValueType Int4{ScalarType::Int4}, Int4Array{ScalarType::Int4, true};
inline constexpr ValueType Float2{ScalarType::Float2}, Float2Array{ScalarType::Float2, true};
inline constexpr ValueType Float3{ScalarType::Float3}, Float3Array{ScalarType::Float3, true};
inline constexpr ValueType Float4{ScalarType::Float4}, Float4Array{ScalarType::Float4, true};
inline constexpr ValueType Double2{ScalarType::Double2}, Double2Array{ScalarType::Double2, true};
inline constexpr ValueType Double3{ScalarType::Double3}, Double3Array{ScalarType::Double3, true};
inline constexpr ValueType Double4{ScalarType::Double4}, Double4Array{ScalarType::Double4, true};
inline constexpr ValueType Point3f{ScalarType::Point3f}, Point3fArray{ScalarType::Point3f, true};
inline constexpr ValueType Point3d{ScalarType::Point3d}, Point3dArray{ScalarType::Point3d, true};
inline constexpr ValueType Normal3f{ScalarType::Normal3f}, Normal3fArray{ScalarType::Normal3f, true};
inline constexpr ValueType Normal3d{ScalarType::Normal3d}, Normal3dArray{ScalarType::Normal3d, true};
inline constexpr ValueType Vector3f{ScalarType::Vector3f}, Vector3fArray{ScalarType::Vector3f, true};
inline constexpr ValueType Vector3d{ScalarType::Vector3d}, Vector3dArray{ScalarType::Vector3d, true};
inline constexpr ValueType Color3f{ScalarType::Color3f}, Color3fArray{ScalarType::Color3f, true};
inline constexpr ValueType Color3d{ScalarType::Color3d}, Color3dArray{ScalarType::Color3d, true};
inline constexpr ValueType Color4f{ScalarType::Color4f}, Color4fArray{ScalarType::Color4f, true};
inline constexpr ValueType Color4d{ScalarType::Color4d}, Color4dArray{ScalarType::Color4d, true};
inline constexpr ValueType TexCoord2f{ScalarType::TexCoord2f}, TexCoord2fArray{ScalarType::TexCoord2f, true};
inline constexpr ValueType TexCoord2d{ScalarType::TexCoord2d}, TexCoord2dArray{ScalarType::TexCoord2d, true};
inline constexpr ValueType Quatf{ScalarType::Quatf}, QuatfArray{ScalarType::Quatf, true};
inline constexpr ValueType Quatd{ScalarType::Quatd}, QuatdArray{ScalarType::Quatd, true};
inline constexpr ValueType Matrix4d{ScalarType::Matrix4d}, Matrix4dArray{ScalarType::Matrix4d, true};
inline constexpr ValueType Dictionary{ScalarType::Dictionary};
}  // namespace types

// The C++ type one element of a ScalarType is stored as.
template <ScalarType S> struct ScalarStorage;
template <> struct ScalarStorage<ScalarType::Bool> { using type = bool; };
template <> struct ScalarStorage<ScalarType::Int> { using type = std::int32_t; };
template <> struct ScalarStorage<ScalarType::UInt> { using type = std::uint32_t; };
template <> struct ScalarStorage<ScalarType::Int64> { using type = std::int64_t; };
template <> struct ScalarStorage<ScalarType::UInt64> { using type = std::uint64_t; };
template <> struct ScalarStorage<ScalarType::Float> { using type = float; };
template <> struct ScalarStorage<ScalarType::Double> { using type = double; };
template <> struct ScalarStorage<ScalarType::String> { using type = std::string; };
template <> struct ScalarStorage<ScalarType::Token> { using type = std::string; };
template <> struct ScalarStorage<ScalarType::Asset> { using type = std::string; };
template <> struct ScalarStorage<ScalarType::Int2> { using type = Vec2i; };
template <> struct ScalarStorage<ScalarType::Int3> { using type = Vec3i; };
template <> struct ScalarStorage<ScalarType::Int4> { using type = Vec4i; };
template <> struct ScalarStorage<ScalarType::Float2> { using type = Vec2f; };
template <> struct ScalarStorage<ScalarType::Float3> { using type = Vec3f; };
template <> struct ScalarStorage<ScalarType::Float4> { using type = Vec4f; };
template <> struct ScalarStorage<ScalarType::Double2> { using type = Vec2d; };
template <> struct ScalarStorage<ScalarType::Double3> { using type = Vec3d; };
template <> struct ScalarStorage<ScalarType::Double4> { using type = Vec4d; };
template <> struct ScalarStorage<ScalarType::Point3f> { using type = Vec3f; };
template <> struct ScalarStorage<ScalarType::Point3d> { using type = Vec3d; };
template <> struct ScalarStorage<ScalarType::Normal3f> { using type = Vec3f; };
template <> struct ScalarStorage<ScalarType::Normal3d> { using type = Vec3d; };
template <> struct ScalarStorage<ScalarType::Vector3f> { using type = Vec3f; };
template <> struct ScalarStorage<ScalarType::Vector3d> { using type = Vec3d; };
template <> struct ScalarStorage<ScalarType::Color3f> { using type = Vec3f; };
template <> struct ScalarStorage<ScalarType::Color3d> { using type = Vec3d; };
template <> struct ScalarStorage<ScalarType::Color4f> { using type = Vec4f; };
template <> struct ScalarStorage<ScalarType::Color4d> { using type = Vec4d; };
template <> struct ScalarStorage<ScalarType::TexCoord2f> { using type = Vec2f; };
template <> struct ScalarStorage<ScalarType::TexCoord2d> { using type = Vec2d; };
template <> struct ScalarStorage<ScalarType::Quatf> { using type = usda::Quatf; };
template <> struct ScalarStorage<ScalarType::Quatd> { using type = usda::Quatd; };
template <> struct ScalarStorage<ScalarType::Matrix4d> { using type = usda::Matrix4d; };
template <> struct ScalarStorage<ScalarType::Dictionary> { using type = usda::Dictionary; };

// The C++ type a whole value of type T is stored as: the element type or a vector of it.
template <ValueType T>
using StorageOf = std::conditional_t<T.isArray,
                                     std::vector<typename ScalarStorage<T.scalar>::type>,
                                     typename ScalarStorage<T.scalar>::type>;

// Calls f.template operator()<S>() with the run-time scalar type as a compile-time one.
template <class F>
decltype(auto) visitScalarType(ScalarType s, F&& f) {
    switch (s) {
        case ScalarType::Bool: return f.template operator()<ScalarType::Bool>();
        case ScalarType::Int: return f.template operator()<ScalarType::Int>();
        case ScalarType::UInt: return f.template operator()<ScalarType::UInt>();
        case ScalarType::Int64: return f.template operator()<ScalarType::Int64>();
        case ScalarType::UInt64: return f.template operator()<ScalarType::UInt64>();
        case ScalarType::Float: return f.template operator()<ScalarType::Float>();
        case ScalarType::Double: return f.template operator()<ScalarType::Double>();
        case ScalarType::String: return f.template operator()<ScalarType::String>();
        case ScalarType::Token: return f.template operator()<ScalarType::Token>();
        case ScalarType::Asset: return f.template operator()<ScalarType::Asset>();
        case ScalarType::Int2: return f.template operator()<ScalarType::Int2>();
        case ScalarType::Int3: return f.template operator()<ScalarType::Int3>();
        case ScalarType::Int4: return f.template operator()<ScalarType::Int4>();
        case ScalarType::Float2: return f.template operator()<ScalarType::Float2>();
        case ScalarType::Float3: return f.template operator()<ScalarType::Float3>();
        case ScalarType::Float4: return f.template operator()<ScalarType::Float4>();
        case ScalarType::Double2: return f.template operator()<ScalarType::Double2>();
        case ScalarType::Double3: return f.template operator()<ScalarType::Double3>();
        case ScalarType::Double4: return f.template operator()<ScalarType::Double4>();
        case ScalarType::Point3f: return f.template operator()<ScalarType::Point3f>();
        case ScalarType::Point3d: return f.template operator()<ScalarType::Point3d>();
        case ScalarType::Normal3f: return f.template operator()<ScalarType::Normal3f>();
        case ScalarType::Normal3d: return f.template operator()<ScalarType::Normal3d>();
        case ScalarType::Vector3f: return f.template operator()<ScalarType::Vector3f>();
        case ScalarType::Vector3d: return f.template operator()<ScalarType::Vector3d>();
        case ScalarType::Color3f: return f.template operator()<ScalarType::Color3f>();
        case ScalarType::Color3d: return f.template operator()<ScalarType::Color3d>();
        case ScalarType::Color4f: return f.template operator()<ScalarType::Color4f>();
        case ScalarType::Color4d: return f.template operator()<ScalarType::Color4d>();
        case ScalarType::TexCoord2f: return f.template operator()<ScalarType::TexCoord2f>();
        case ScalarType::TexCoord2d: return f.template operator()<ScalarType::TexCoord2d>();
        case ScalarType::Quatf: return f.template operator()<ScalarType::Quatf>();
        case ScalarType::Quatd: return f.template operator()<ScalarType::Quatd>();
        case ScalarType::Matrix4d: return f.template operator()<ScalarType::Matrix4d>();
        case ScalarType::Dictionary: break;
    }
    return f.template operator()<ScalarType::Dictionary>();
}

}  // namespace opal::usda
