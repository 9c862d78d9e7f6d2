// Reversible transforms that make the sidecar's big arrays compress better under zstd,
// applied while streaming (fixed-size blocks, never a whole copy of an array):
//   float planes: a float32 array is stored as byte plane 0 of every value (the low
//     mantissa bytes), then plane 1, 2, 3 (sign and exponent): the exponent bytes of
//     nearby values are alike, which zstd exploits. On a synthetic transfer matrix this
//     cut the compressed values from 94% to 86% of their raw size (zstd level 3).
//   half planes: where 11 significant bits are plenty (the environment transfer, whose
//     coefficients are themselves approximations), a float array is stored as a
//     power-of-two scale 2^e and the IEEE binary16 bits of v 2^-e, as two byte planes. e
//     puts the largest magnitude in (2^14, 2^15], so every value down to 2^-28 of the
//     largest keeps a relative rounding error <= 2^-11; smaller ones keep an absolute
//     error <= 2^-39 of the largest (half subnormals). Half the bytes of float planes.
//     (The transfer's values, once stored this way, now go on a weighted quantization
//     grid as varints: transfer_value_grid.h.)
//   varints: signed integers (quantized transfer values, transfer_value_grid.h) as zigzag
//     LEB128, most of them one byte, behind their total byte count.
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

// Half planes: i32 e, then plane 0 (low bytes) and plane 1 (high bytes) of the binary16
// values. Values must be finite. readHalfPlanes rejects an e outside [-160, 111] (so that
// every decoded value is a finite float) and half infinities and NaNs, naming `what`.
void writeHalfPlanes(ChunkSink& sink, std::span<const float> values);
// The half planes' e: max |v| 2^-e in (2^14, 2^15], so every value keeps 11 significant
// bits down to 2^-14 of 2^15 (0 for all zeros or a non-finite maximum). Also what the
// delegate's binary16 working copies scale by (delegate/relight/scaled_half.h).
int halfScaleExponent(std::span<const float> values);
std::vector<float> readHalfPlanes(ChunkSource& source, std::uint64_t count, std::string_view what);
// Replaces each value by what writeHalfPlanes followed by readHalfPlanes gives back, so a
// bake can measure what it stores. Idempotent.
void roundToHalfPlanes(std::span<float> values);

// Varints: u64 byte count B, then the values, each zigzag-mapped (0, -1, 1, -2, ... ->
// 0, 1, 2, 3, ...) and written as LEB128 (7 bits a byte, low first, high bit = more).
// readVarints needs exactly `count` values in exactly B bytes, none longer than 10 bytes
// or beyond 64 bits, and names `what` in its errors.
void writeVarints(ChunkSink& sink, std::span<const std::int64_t> values);
std::vector<std::int64_t> readVarints(ChunkSource& source, std::uint64_t count, std::string_view what);

// `offsets` (rows + 1 entries, from 0 to indices.size()) must already be valid.
template <class Offset>
void writeRowDeltas(ChunkSink& sink, std::span<const Offset> offsets, std::span<const std::uint32_t> indices);
template <class Offset>
std::vector<std::uint32_t> readRowDeltas(ChunkSource& source, std::span<const Offset> offsets,
                                         std::string_view what);

}  // namespace opal
