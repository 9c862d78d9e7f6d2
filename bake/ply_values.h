// Reads the data section of a PLY file value by value, in the header's format (ASCII
// tokens or binary little/big endian). Every read is bounded by the bytes that remain,
// so a declared count can be checked against the file before anything is allocated.
#pragma once

#include "bake/ply_header.h"

#include <cstdint>
#include <string_view>

namespace opal {

class PlyValueReader {
public:
    // data: the bytes after the header (PlyHeader::dataOffset).
    PlyValueReader(std::string_view data, PlyFormat format) : data_(data), format_(format) {}

    // One value of the given type. Throws opal::Error ("the data ends early", "'x1' is
    // not a number") without a location: the caller adds the element and property.
    double real(PlyScalar type);
    // One value of an integer type, exactly. Throws as real() does, and for a float type.
    std::int64_t integer(PlyScalar type);

    // True when `count` more values of `type` could still follow (ASCII values take at
    // least one character and one separator): a bound on declared counts before any
    // allocation. The last ASCII value may lack its separator.
    bool couldHold(std::uint64_t count, PlyScalar type) const;

private:
    std::string_view token();
    std::string_view bytes(std::size_t size);

    std::string_view data_;
    PlyFormat format_;
    std::size_t pos_ = 0;
};

}  // namespace opal
