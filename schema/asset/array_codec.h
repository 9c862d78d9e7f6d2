// Reversible transforms that make the sidecar's big arrays compress better under zstd,
// applied while streaming (fixed-size blocks, never a whole copy of an array):
//   float planes: a float32 array is stored as byte plane 0 of every value (the low
//     mantissa bytes), then plane 1, 2, 3 (sign and exponent): the exponent bytes of
//     nearby values are alike, which zstd exploits. On a synthetic transfer matrix this
//     cut the compressed values from 94% to 86% of their raw size (zstd level 3).
//   row deltas: CSR column indices are stored per row as differences to the previous
//     index of the same row (the first as is), modulo 2^32, so any order round-trips
//     exactly and sorted rows become small numbers: compressed columns went from 16.5% to
//     12.8% of their raw size on the same matrix.
#pragma once

#include "schema/asset/chunk_sink.h"
#include "schema/asset/chunk_source.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace opal {

void writeFloatPlanes(ChunkSink& sink, std::span<const float> values);
std::vector<float> readFloatPlanes(ChunkSource& source, std::uint64_t count, std::string_view what);

// `offsets` (rows + 1 entries, from 0 to indices.size()) must already be valid.
template <class Offset>
void writeRowDeltas(ChunkSink& sink, std::span<const Offset> offsets, std::span<const std::uint32_t> indices);
template <class Offset>
std::vector<std::uint32_t> readRowDeltas(ChunkSource& source, std::span<const Offset> offsets,
                                         std::string_view what);

}  // namespace opal
