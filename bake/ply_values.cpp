#include "bake/ply_values.h"

#include "schema/error.h"

#include <bit>
#include <charconv>
#include <string>
#include <type_traits>

namespace opal {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// The value of `size` bytes in file order, as an unsigned integer in host order.
std::uint64_t unsignedBits(std::string_view raw, bool bigEndian) {
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const std::size_t byte = bigEndian ? raw.size() - 1 - i : i;
        bits |= std::uint64_t(static_cast<unsigned char>(raw[byte])) << (8 * i);
    }
    return bits;
}

template <typename T>
T fromBits(std::uint64_t bits) {
    using Unsigned = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                     std::conditional_t<sizeof(T) == 2, std::uint16_t,
                     std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    return std::bit_cast<T>(static_cast<Unsigned>(bits));
}

double binaryValue(std::string_view raw, PlyScalar type, bool bigEndian) {
    const std::uint64_t bits = unsignedBits(raw, bigEndian);
    switch (type) {
        case PlyScalar::Int8: return fromBits<std::int8_t>(bits);
        case PlyScalar::UInt8: return fromBits<std::uint8_t>(bits);
        case PlyScalar::Int16: return fromBits<std::int16_t>(bits);
        case PlyScalar::UInt16: return fromBits<std::uint16_t>(bits);
        case PlyScalar::Int32: return fromBits<std::int32_t>(bits);
        case PlyScalar::UInt32: return fromBits<std::uint32_t>(bits);
        case PlyScalar::Float32: return fromBits<float>(bits);
        case PlyScalar::Float64: return fromBits<double>(bits);
    }
    return 0.0;
}

}  // namespace

std::string_view PlyValueReader::token() {
    while (pos_ < data_.size() && isBlank(data_[pos_])) ++pos_;
    if (pos_ >= data_.size()) throw Error("the data ends early");
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !isBlank(data_[pos_])) ++pos_;
    return data_.substr(start, pos_ - start);
}

std::string_view PlyValueReader::bytes(std::size_t size) {
    if (data_.size() - pos_ < size) throw Error("the data ends early");
    const std::string_view raw = data_.substr(pos_, size);
    pos_ += size;
    return raw;
}

double PlyValueReader::real(PlyScalar type) {
    if (format_ != PlyFormat::Ascii)
        return binaryValue(bytes(plyScalarSize(type)), type, format_ == PlyFormat::BinaryBigEndian);
    const std::string_view text = token();
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        throw Error("'" + std::string(text) + "' is not a number");
    return value;
}

std::int64_t PlyValueReader::integer(PlyScalar type) {
    if (!plyScalarIsInteger(type)) throw Error("expected an integer type, the header declares a float type");
    if (format_ != PlyFormat::Ascii)
        return std::int64_t(binaryValue(bytes(plyScalarSize(type)), type, format_ == PlyFormat::BinaryBigEndian));
    const std::string_view text = token();
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        throw Error("'" + std::string(text) + "' is not an integer");
    return value;
}

bool PlyValueReader::couldHold(std::uint64_t count, PlyScalar type) const {
    const std::uint64_t remaining = data_.size() - pos_;
    const std::uint64_t perValue = format_ == PlyFormat::Ascii ? 2 : plyScalarSize(type);
    return count <= (remaining + (format_ == PlyFormat::Ascii ? 1 : 0)) / perValue;
}

}  // namespace opal
