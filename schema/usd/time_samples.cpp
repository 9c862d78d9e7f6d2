#include "schema/usd/time_samples.h"

#include <Imath/ImathQuat.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace opal::usda {
namespace {

template <class T>
inline constexpr bool isFloating = std::is_floating_point_v<T>;

template <class T>
struct IsFloatingArray : std::false_type {};
template <class E, std::size_t N>
struct IsFloatingArray<std::array<E, N>> : std::bool_constant<isFloating<E> || IsFloatingArray<E>::value> {};

template <class T>
T lerp(const T& a, const T& b, double t) {
    if constexpr (isFloating<T>) {
        return T(a + (b - a) * t);
    } else {
        T out{};
        for (std::size_t i = 0; i < a.size(); ++i) out[i] = lerp(a[i], b[i], t);
        return out;
    }
}

// Quaternions (real, i, j, k) along the shorter arc, as GfSlerp.
template <class Q>
Q slerp(const Q& a, const Q& b, double t) {
    using E = typename Q::value_type;
    const Imath::Quat<double> qa(a[0], a[1], a[2], a[3]), qb(b[0], b[1], b[2], b[3]);
    const Imath::Quat<double> q = Imath::slerpShortestArc(qa.normalized(), qb.normalized(), t);
    return {E(q.r), E(q.v.x), E(q.v.y), E(q.v.z)};
}

// The value between two samples of the same type, or nullopt where USD holds instead.
std::optional<Value> interpolate(const Value& a, const Value& b, double t) {
    const ValueType type = a.type();
    return visitScalarType(type.scalar, [&]<ScalarType S>() -> std::optional<Value> {
        using E = typename ScalarStorage<S>::type;
        if constexpr (!isFloating<E> && !IsFloatingArray<E>::value) {
            return std::nullopt;
        } else {
            const auto element = [&](const E& x, const E& y) {
                if constexpr (S == ScalarType::Quatf || S == ScalarType::Quatd) {
                    return slerp(x, y, t);
                } else {
                    return lerp(x, y, t);
                }
            };
            if (!type.isArray) {
                return Value::make<ValueType{S}>(element(std::get<E>(a.data()), std::get<E>(b.data())), a.location());
            } else {  // NOLINT(readability-else-after-return): the two branches are the two shapes
                const auto& x = std::get<std::vector<E>>(a.data());
                const auto& y = std::get<std::vector<E>>(b.data());
                if (x.size() != y.size()) return std::nullopt;
                std::vector<E> out(x.size());
                for (std::size_t i = 0; i < x.size(); ++i) out[i] = element(x[i], y[i]);
                return Value::make<ValueType{S, true}>(std::move(out), a.location());
            }
        }
    });
}

}  // namespace

std::optional<Value> valueAt(const Attribute& attribute, double timeCode) {
    const std::vector<TimeSample>& samples = attribute.timeSamples;
    if (samples.empty()) return attribute.value;
    const auto upper = std::upper_bound(samples.begin(), samples.end(), timeCode,
                                        [](double time, const TimeSample& s) { return time < s.time; });
    if (upper == samples.begin()) return samples.front().value;
    const TimeSample& lower = *(upper - 1);
    if (upper == samples.end() || lower.time == timeCode || lower.value.isNone() || upper->value.isNone())
        return lower.value;
    const double t = (timeCode - lower.time) / (upper->time - lower.time);
    std::optional<Value> between = interpolate(lower.value, upper->value, t);
    return between ? std::move(between) : lower.value;
}

Attribute attributeAt(const Attribute& attribute, double timeCode) {
    Attribute at = attribute;
    at.value = valueAt(attribute, timeCode);
    at.timeSamples.clear();
    return at;
}

Prim propertiesAt(const Prim& prim, double timeCode) {
    Prim at;
    at.specifier = prim.specifier;
    at.typeName = prim.typeName;
    at.name = prim.name;
    at.comment = prim.comment;
    at.metadata = prim.metadata;
    at.apiSchemas = prim.apiSchemas;
    at.references = prim.references;
    at.inherits = prim.inherits;
    at.location = prim.location;
    at.properties.reserve(prim.properties.size());
    for (const Property& p : prim.properties) {
        const auto* attribute = std::get_if<Attribute>(&p);
        at.properties.push_back(attribute && !attribute->timeSamples.empty() ? Property(attributeAt(*attribute, timeCode))
                                                                             : p);
    }
    return at;
}

bool hasTimeSamples(const Prim& prim) {
    return std::any_of(prim.properties.begin(), prim.properties.end(), [](const Property& p) {
        const auto* attribute = std::get_if<Attribute>(&p);
        return attribute && !attribute->timeSamples.empty();
    });
}

bool mightBeTimeVarying(const Attribute& attribute) { return attribute.timeSamples.size() > 1; }

bool mightBeTimeVarying(const Prim& prim) {
    return std::any_of(prim.properties.begin(), prim.properties.end(), [](const Property& p) {
        const auto* attribute = std::get_if<Attribute>(&p);
        return attribute && mightBeTimeVarying(*attribute);
    });
}

}  // namespace opal::usda
