// The consistency rules of a sidecar's contents (SIDECAR.md, "Validation"). The reader
// applies them to what it decoded, the writer to what it is asked to write, so a file
// Opal writes is always one Opal reads. `context` prefixes every message and names the
// file and chunk ("a.opal: chunk 'TRNS'"); each check throws opal::Error.
#pragma once

#include "schema/asset/cube_map.h"
#include "schema/asset/translucent_asset.h"
#include "schema/scatter/fresnel_moments.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace opal::sidecar {

inline constexpr std::uint32_t kMaxLog2ChartSize = 15;
inline constexpr std::uint64_t kMaxSamples = std::uint64_t(1) << 31;
inline constexpr std::uint32_t kMaxBasisFunctions = 256;
// What the runtime renders is what a reader accepts: one limit each, defined beside the
// code that imposes it (CubeMapLayout's face size, the Fresnel response's terms).
inline constexpr std::uint32_t kMaxCubeFaceSize = CubeMapLayout::kMaxFaceSize;
inline constexpr std::uint32_t kMaxFresnelTerms = std::uint32_t(opal::kMaxFresnelTerms);
// |v| of any environment transport value: v_m(t) = mu P_m(mu) Omega_t with |P_m| <= 1 on
// [0, 1], so the vector's L1 norm is at most the sphere's 4 pi steradians, and an
// orthonormal Haar coefficient is at most that norm (1% for binary16 rounding).
inline constexpr double kMaxEnvironmentValue = 4.0 * 3.14159265358979323846 * 1.01;
inline constexpr std::uint32_t kMaxNameBytes = 4096;
inline constexpr float kUnitNormalTolerance = 1e-3f;    // | |n| - 1 |
inline constexpr double kWeightSumTolerance = 1e-3;     // | sum_j w_vj - 1 |

void checkName(std::string_view name, std::string_view context);
void checkUnitsPerMm(double unitsPerMm, std::string_view context);
void checkLayout(const ChartLayout& layout, std::string_view context);
void checkSamples(std::span<const SurfaceSample> samples, std::uint64_t expected, std::string_view context);

// CSR pieces, in the order a reader can check them while decoding.
template <class Offset>
void checkOffsets(std::span<const Offset> offsets, std::uint64_t rows, std::uint64_t entries,
                  std::string_view context, std::string_view what);
template <class Offset>
void checkIndices(std::span<const Offset> offsets, std::span<const std::uint32_t> indices,
                  std::uint64_t bound, bool ascending, std::string_view context, std::string_view what);
void checkFinite(std::span<const float> values, std::string_view context, std::string_view what);

void checkWeightSums(const VertexWeights& weights, std::string_view context);
void checkVertexWeights(const VertexWeights& weights, std::uint64_t samples, std::string_view context);
void checkTransferHeader(std::uint64_t basisCount, double keepFraction, double energyFraction,
                         std::string_view context);
void checkMatrixShape(const SparseMatrix& m, std::uint64_t samples, std::string_view context,
                      std::string_view what);
// A matrix's value step (transfer_value_grid.h): finite and >= 0.
void checkValueStep(double step, std::string_view context, std::string_view what);
void checkTransfer(const CompressedTransfer& transfer, std::uint64_t samples, std::string_view context);
// CompressedTransfer::harmonics: empty, or samples x K x Q finite values for a harmonic set
// of Q = 9 or 36 functions whose frame is finite with a positive inverse scale.
void checkHarmonics(const CompressedTransfer& transfer, std::uint64_t samples, std::string_view context);
void checkEnvironmentHeader(const EnvironmentTransfer& env, std::string_view context);
// Rows of the environment CSR: 0 (not baked) or samples * fresnelTerms.
std::uint64_t environmentRows(const EnvironmentTransfer& env, std::uint64_t samples);
void checkEnvironment(const EnvironmentTransfer& env, std::uint64_t samples, std::string_view context);

}  // namespace opal::sidecar
