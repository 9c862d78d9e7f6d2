#include "schema/asset/sidecar_checks.h"

#include "schema/asset/normal_harmonics.h"

#include "schema/error.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace opal::sidecar {
namespace {

[[noreturn]] void fail(std::string_view context, const std::string& problem) {
    throw Error(std::string(context) + ": " + problem);
}

std::string str(std::uint64_t v) { return std::to_string(v); }

std::string str(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string at(std::string_view what, std::uint64_t i) { return std::string(what) + "[" + str(i) + "]"; }

bool isFinite(const Imath::V3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void checkSample(const SurfaceSample& s, std::uint64_t i, std::string_view context) {
    if (!isFinite(s.position)) fail(context, "sample " + str(i) + ": position is not finite");
    if (!isFinite(s.normal)) fail(context, "sample " + str(i) + ": normal is not finite");
    float length = s.normal.length();
    if (std::abs(length - 1.0f) > kUnitNormalTolerance)
        fail(context, "sample " + str(i) + ": normal has length " + str(double(length)) + ", not 1");
    if (!(s.area > 0.0f) || !std::isfinite(s.area))
        fail(context, "sample " + str(i) + ": area " + str(double(s.area)) + " is not positive and finite");
}

bool isPowerOfTwo(std::uint32_t v) { return v != 0 && (v & (v - 1)) == 0; }

}  // namespace

void checkName(std::string_view name, std::string_view context) {
    if (name.size() > kMaxNameBytes)
        fail(context, "asset name of " + str(std::uint64_t(name.size())) + " bytes, more than " + str(std::uint64_t(kMaxNameBytes)));
}

void checkUnitsPerMm(double unitsPerMm, std::string_view context) {
    if (!(unitsPerMm > 0.0) || !std::isfinite(unitsPerMm))
        fail(context, "unitsPerMm " + str(unitsPerMm) + " is not positive and finite");
}

void checkLayout(const ChartLayout& layout, std::string_view context) {
    if (layout.charts == 0) fail(context, "chart layout has no charts");
    if (layout.log2Size > kMaxLog2ChartSize)
        fail(context, "chart size 2^" + str(std::uint64_t(layout.log2Size)) + " exceeds 2^" + str(std::uint64_t(kMaxLog2ChartSize)));
    if (layout.cells() > kMaxSamples)
        fail(context, str(std::uint64_t(layout.charts)) + " charts of 2^" + str(std::uint64_t(layout.log2Size)) +
                          " x 2^" + str(std::uint64_t(layout.log2Size)) + " cells exceed " + str(kMaxSamples) + " samples");
}

void checkSamples(std::span<const SurfaceSample> samples, std::uint64_t expected, std::string_view context) {
    if (samples.size() != expected)
        fail(context, str(std::uint64_t(samples.size())) + " samples, the chart layout has " + str(expected) + " cells");
    for (std::size_t i = 0; i < samples.size(); ++i) checkSample(samples[i], i, context);
}

template <class Offset>
void checkOffsets(std::span<const Offset> offsets, std::uint64_t rows, std::uint64_t entries,
                  std::string_view context, std::string_view what) {
    if (offsets.empty() || offsets.size() - 1 != rows)
        fail(context, std::string(what) + ": " + str(std::uint64_t(offsets.size())) + " offsets for " + str(rows) + " rows");
    if (offsets[0] != 0) fail(context, at(what, 0) + " is " + str(std::uint64_t(offsets[0])) + ", not 0");
    for (std::size_t r = 0; r < rows; ++r)
        if (offsets[r + 1] < offsets[r])
            fail(context, std::string(what) + " decrease at row " + str(std::uint64_t(r)) + ": " +
                              str(std::uint64_t(offsets[r])) + " then " + str(std::uint64_t(offsets[r + 1])));
    if (offsets[rows] != entries)
        fail(context, std::string(what) + " end at " + str(std::uint64_t(offsets[rows])) + ", not at the " +
                          str(entries) + " entries");
}

template <class Offset>
void checkIndices(std::span<const Offset> offsets, std::span<const std::uint32_t> indices,
                  std::uint64_t bound, bool ascending, std::string_view context, std::string_view what) {
    for (std::size_t r = 0; r + 1 < offsets.size(); ++r) {
        for (std::uint64_t j = offsets[r]; j < offsets[r + 1]; ++j) {
            if (indices[j] >= bound)
                fail(context, std::string(what) + " row " + str(std::uint64_t(r)) + ": index " +
                                  str(std::uint64_t(indices[j])) + " >= " + str(bound));
            if (ascending && j > offsets[r] && indices[j] <= indices[j - 1])
                fail(context, std::string(what) + " row " + str(std::uint64_t(r)) + ": indices " +
                                  str(std::uint64_t(indices[j - 1])) + ", " + str(std::uint64_t(indices[j])) +
                                  " not strictly ascending");
        }
    }
}

void checkFinite(std::span<const float> values, std::string_view context, std::string_view what) {
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i])) fail(context, at(what, i) + " = " + str(double(values[i])) + " is not finite");
}

void checkWeightSums(const VertexWeights& w, std::string_view context) {
    for (std::size_t v = 0; v + 1 < w.offsets.size(); ++v) {
        double sum = 0.0;
        for (std::uint32_t j = w.offsets[v]; j < w.offsets[v + 1]; ++j) sum += w.weights[j];
        if (std::abs(sum - 1.0) > kWeightSumTolerance)
            fail(context, "vertex " + str(std::uint64_t(v)) + ": weights sum to " + str(sum) + ", not 1");
    }
}

void checkVertexWeights(const VertexWeights& w, std::uint64_t samples, std::string_view context) {
    if (w.offsets.empty()) fail(context, "no vertex offsets (a CSR needs vertices + 1)");
    if (w.samples.size() != w.weights.size())
        fail(context, str(std::uint64_t(w.samples.size())) + " sample indices but " +
                          str(std::uint64_t(w.weights.size())) + " weights");
    std::span<const std::uint32_t> offsets = w.offsets;
    checkOffsets(offsets, offsets.size() - 1, w.samples.size(), context, "vertex offsets");
    checkIndices(offsets, w.samples, samples, false, context, "vertex samples");
    checkFinite(w.weights, context, "weights");
    checkWeightSums(w, context);
}

void checkTransferHeader(std::uint64_t basisCount, double keepFraction, double energyFraction,
                         std::string_view context) {
    if (basisCount == 0 || basisCount > kMaxBasisFunctions)
        fail(context, "K = " + str(basisCount) + " basis functions, outside [1, " + str(std::uint64_t(kMaxBasisFunctions)) + "]");
    if (!(keepFraction > 0.0 && keepFraction <= 1.0))
        fail(context, "keep fraction " + str(keepFraction) + " outside (0, 1]");
    if (!(energyFraction > 0.0 && energyFraction <= 1.0))
        fail(context, "energy fraction " + str(energyFraction) + " outside (0, 1]");
}

void checkMatrixShape(const SparseMatrix& m, std::uint64_t samples, std::string_view context,
                      std::string_view what) {
    if (m.rows != samples || m.cols != samples)
        fail(context, std::string(what) + ": " + str(std::uint64_t(m.rows)) + " x " + str(std::uint64_t(m.cols)) +
                          ", expected " + str(samples) + " x " + str(samples) + " (one row and column per sample)");
}

void checkValueStep(double step, std::string_view context, std::string_view what) {
    if (!(std::isfinite(step) && step >= 0.0))
        fail(context, std::string(what) + ": value step " + str(step) + " is not a finite number >= 0");
}

void checkTransfer(const CompressedTransfer& t, std::uint64_t samples, std::string_view context) {
    checkTransferHeader(t.perBasis.size(), t.keepFraction, t.energyFraction, context);
    if (!t.valueSteps.empty() && t.valueSteps.size() != t.perBasis.size())
        fail(context, str(std::uint64_t(t.valueSteps.size())) + " value steps for " +
                          str(std::uint64_t(t.perBasis.size())) + " matrices");
    for (std::size_t k = 0; k < t.perBasis.size(); ++k) {
        const SparseMatrix& m = t.perBasis[k];
        std::string what = "matrix " + str(std::uint64_t(k));
        checkMatrixShape(m, samples, context, what);
        if (m.columns.size() != m.values.size())
            fail(context, what + ": " + str(std::uint64_t(m.columns.size())) + " column indices but " +
                              str(std::uint64_t(m.values.size())) + " values");
        std::span<const std::uint64_t> offsets = m.rowOffsets;
        checkOffsets(offsets, m.rows, m.columns.size(), context, what + " row offsets");
        checkIndices(offsets, m.columns, m.cols, true, context, what + " columns");
        checkFinite(m.values, context, what + " values");
        checkValueStep(t.valueStep(k), context, what);
    }
}

void checkHarmonics(const CompressedTransfer& transfer, std::uint64_t samples, std::string_view context) {
    const std::span<const float> harmonics = transfer.harmonics;
    if (harmonics.empty()) return;
    const HarmonicSet& set = transfer.harmonicSet;
    if (!isHarmonicCount(set.count))
        fail(context, "a harmonic set of " + str(std::uint64_t(set.count)) + " functions, expected 9 or 36");
    if (!(std::isfinite(set.centre.x) && std::isfinite(set.centre.y) && std::isfinite(set.centre.z) &&
          std::isfinite(set.inverseScale) && set.inverseScale > 0.0f))
        fail(context, "the harmonic set's frame (centre and inverse scale) is not finite with a positive scale");
    const std::uint64_t expected = samples * transfer.perBasis.size() * set.count;
    if (harmonics.size() != expected)
        fail(context, str(std::uint64_t(harmonics.size())) + " harmonic transfer values, expected samples x K x " +
                          str(std::uint64_t(set.count)) + " = " + str(expected));
    checkFinite(harmonics, context, "harmonic transfer values");
}

void checkEnvironmentHeader(const EnvironmentTransfer& env, std::string_view context) {
    if (!isPowerOfTwo(env.cubeFaceSize) || env.cubeFaceSize > kMaxCubeFaceSize)
        fail(context, "cube face size " + str(std::uint64_t(env.cubeFaceSize)) + " is not a power of two in [1, " +
                          str(std::uint64_t(kMaxCubeFaceSize)) + "]");
    if (env.fresnelTerms == 0 || env.fresnelTerms > kMaxFresnelTerms)
        fail(context, str(std::uint64_t(env.fresnelTerms)) + " Fresnel terms, outside [1, " +
                          str(std::uint64_t(kMaxFresnelTerms)) + "]");
}

std::uint64_t environmentRows(const EnvironmentTransfer& env, std::uint64_t samples) {
    return env.offsets.empty() ? 0 : samples * env.fresnelTerms;
}

void checkEnvironment(const EnvironmentTransfer& env, std::uint64_t samples, std::string_view context) {
    checkEnvironmentHeader(env, context);
    if (env.indices.size() != env.values.size())
        fail(context, str(std::uint64_t(env.indices.size())) + " indices but " + str(std::uint64_t(env.values.size())) + " values");
    if (env.offsets.empty()) {
        if (!env.indices.empty()) fail(context, "entries without row offsets");
        return;
    }
    std::span<const std::uint32_t> offsets = env.offsets;
    std::uint64_t cubeCells = 6ull * env.cubeFaceSize * env.cubeFaceSize;
    checkOffsets(offsets, environmentRows(env, samples), env.indices.size(), context, "row offsets");
    checkIndices(offsets, env.indices, cubeCells, true, context, "cube-map indices");
    checkFinite(env.values, context, "values");
    for (std::size_t i = 0; i < env.values.size(); ++i)
        if (std::abs(env.values[i]) > kMaxEnvironmentValue)
            fail(context, "value " + str(std::uint64_t(i)) + " is " + std::to_string(env.values[i]) +
                              ": a transport value's magnitude is at most 4 pi (visibility x cosine x Fresnel "
                              "moment x solid angle)");
}

template void checkOffsets<std::uint32_t>(std::span<const std::uint32_t>, std::uint64_t, std::uint64_t,
                                          std::string_view, std::string_view);
template void checkOffsets<std::uint64_t>(std::span<const std::uint64_t>, std::uint64_t, std::uint64_t,
                                          std::string_view, std::string_view);
template void checkIndices<std::uint32_t>(std::span<const std::uint32_t>, std::span<const std::uint32_t>,
                                          std::uint64_t, bool, std::string_view, std::string_view);
template void checkIndices<std::uint64_t>(std::span<const std::uint64_t>, std::span<const std::uint32_t>,
                                          std::uint64_t, bool, std::string_view, std::string_view);

}  // namespace opal::sidecar
