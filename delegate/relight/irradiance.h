// The irradiance at an asset's samples in Fresnel-moment form (docs/ARCHITECTURE.md#irradiance),
// and the samples placed in the world.
//
// E(x_i) = integral L_i(w) F_t(eta, w) max(0, n.w) dw needs eta, a material parameter.
// So that an eta edit stays a material edit (no new sparse products), lights deliver
// moments E_m(x_i) for m < terms and the relighting engine forms
//     E(x_i; eta) = sum_m c_m(eta) E_m(x_i),   c_m = fresnelMoments(eta, terms).
// Environment lights: E_m = integral L V mu P_m(mu) dw (the baked transfer vectors).
// Analytic lights: E_m = E_perp mu h_m(mu) with the response of fresnel_response.h.
//
// Units: RGB in the working color space; E in the lights' radiometric unit per square
// scene unit (lights are specified in world space, so 1/d^2 uses scene units).
#pragma once

#include "schema/asset/translucent_asset.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

struct IrradianceMoments {
    std::uint32_t samples = 0;
    std::uint32_t terms = 0;
    FresnelBasis basis = FresnelBasis::Legendre;  // the P_m the moments are taken against
    std::vector<float> values;  // samples x terms x 3 (RGB): values[(i * terms + m) * 3 + c]

    IrradianceMoments() = default;
    IrradianceMoments(std::uint32_t samples, std::uint32_t terms, FresnelBasis basis = FresnelBasis::Legendre);  // zero

    std::uint32_t channels() const { return 3 * terms; }
    float* sample(std::size_t i) { return values.data() + i * channels(); }
    const float* sample(std::size_t i) const { return values.data() + i * channels(); }

    // E(x_i; eta) = sum_m c[m] E_m(x_i), RGB: samples x 3. c.size() must equal terms.
    std::vector<float> combine(std::span<const double> c) const;
    // The same into rgb (resized), in parallel: what a light edit re-forms, into a buffer
    // it keeps.
    void combine(std::span<const double> c, std::vector<float>& rgb) const;
    // Adds another set of the same shape and basis (throws opal::Error otherwise).
    IrradianceMoments& operator+=(const IrradianceMoments& other);
};

// The asset's samples in world space. The transfer is baked in object-space lengths
// (unitsPerMm), so a mesh transform may rotate and translate; a uniform scale is accepted
// as a display change only (the object scatters as baked, at its baked size in mm);
// anything else (non-uniform scale, shear, projection) throws opal::Error.
struct PlacedSamples {
    std::vector<Imath::V3f> positions;  // world
    std::vector<Imath::V3f> normals;    // world, unit
};

PlacedSamples placeSamples(std::span<const SurfaceSample> samples, const Imath::M44d& objectToWorld);

// The rotation part of a rotation x uniform scale x translation (row vectors), scale
// removed. Throws opal::Error (prefixed with context) for any other matrix.
Imath::M33d rotationOf(const Imath::M44d& transform, const char* context);

}  // namespace opal
