// The header of a PLY file: its format and the elements it declares, each with its
// properties, in file order. Opal reads PLY through Assimp except for what Assimp does not
// decode (triangle strips, bake/ply_triangle_strips.h); this header tells the two apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyScalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// Bytes one value of the type takes in a binary file.
std::size_t plyScalarSize(PlyScalar type);
bool plyScalarIsInteger(PlyScalar type);

struct PlyProperty {
    std::string name;
    PlyScalar type = PlyScalar::Float32;  // the values' type (a list's items)
    bool isList = false;
    PlyScalar countType = PlyScalar::UInt8;  // a list's length type
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    std::size_t dataOffset = 0;  // the first byte after "end_header" and its line end

    // The element called `name`, or nullptr.
    const PlyElement* find(std::string_view name) const;
};

// Parses the header at the start of `bytes` (a whole file). Throws opal::Error
// "<file>:<line>: <problem>" for a missing "ply" magic, an unknown format or type, a
// property outside an element, a malformed line, or no "end_header".
PlyHeader parsePlyHeader(std::string_view bytes, const std::string& file);

}  // namespace opal
