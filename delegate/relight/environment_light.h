// The dome light (docs/ARCHITECTURE.md#dome-light, after Ng et al. 2003): a lat-long radiance map,
// rotated by the light's transform, resampled to the cube map of the asset's environment transfer
// (in the asset's object space); from it the dome's unoccluded integral at every normal
// (dome_convolution.h) less the product of the Haar-transformed map with every sample's baked
// occluded residual: E_m(x_i) = U_m(n_i) - <O_{i,m}, L> (environment_vectors.h). Rotating the
// dome or the mesh re-projects the map and sums U again, without rays. The baked visibility is
// the asset's own (self) occlusion: other meshes do not shadow a dome.
//
// Orientation (UsdLux DomeLight, which follows OpenEXR's latitude-longitude maps; Poly
// Haven's .hdr maps are authored for it): +Y is up; the image's horizontal coordinate
// u in [0, 1] (left to right) is longitude phi = pi (1 - 2u) and its vertical coordinate
// v in [0, 1] (top to bottom) is latitude theta = pi (1/2 - v), with
//     direction = (cos theta sin phi, sin theta, cos theta cos phi):
// the image centre looks along +Z, u = 1/4 along +X, the left and right edges along -Z,
// the top row at +Y. Pixel (x, y) of a W x H map covers [x, x+1]/W x [y, y+1]/H.
// The dome's transform maps dome directions to world directions (row vectors).
//
// Units: radiance = color * intensity * 2^exposure * map value (`normalize` has no effect
// on a dome, as in UsdLux). The map is float RGB already converted to the working color
// space (the caller converts, e.g. from "Linear Rec.709 (sRGB)" for .hdr files).
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "delegate/relight/irradiance.h"
#include "schema/asset/cube_map.h"
#include "schema/scatter/rgb.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <memory>
#include <span>
#include <vector>

namespace opal {

class LatLongMap {
public:
    // rgb: width x height x 3 floats, row-major, top row first. Throws opal::Error on a size
    // mismatch, a non-positive size or a value that is not finite, negative or above
    // kMaxEmittedRadiance (light_emission.h).
    LatLongMap(int width, int height, std::vector<float> rgb);

    int width() const { return levels_.front().width; }
    // The largest value of any channel of any pixel.
    float maxValue() const { return maxValue_; }
    int height() const { return levels_.front().height; }

    // The orientation above: (u, v) <-> unit direction in the dome's space.
    static Imath::V3d direction(double u, double v);
    static Imath::V2d coordinates(const Imath::V3d& direction);

    // Radiance averaged over about `footprint` radians around direction (u, v): bilinear on
    // the level of a box-filtered pyramid whose pixels are about `footprint` tall.
    Imath::V3f sample(double u, double v, double footprint) const;
    // The same in two steps, for callers that look up many directions at one footprint:
    // the level sample() picks, and the bilinear lookup on it (float arithmetic).
    int levelFor(double footprint) const;
    Imath::V3f sampleLevel(int level, float u, float v) const { return bilinear(levels_[std::size_t(level)], u, v); }
    // One level's pixels (width x height x 3 floats, top row first), for vectorized lookups
    // that reproduce sampleLevel (dome_lookup.h). level < levels().
    struct LevelPixels {
        int width = 0, height = 0;
        const float* rgb = nullptr;
    };
    int levels() const { return int(levels_.size()); }
    LevelPixels levelPixels(int level) const {
        const Level& l = levels_[std::size_t(level)];
        return {l.width, l.height, l.rgb.data()};
    }

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<float> rgb;
    };
    static Level halve(const Level& fine);
    static Imath::V3f bilinear(const Level& level, float u, float v);

    std::vector<Level> levels_;  // [0] full resolution, then halved down to one row
    float maxValue_ = 0.0f;
};

class EnvironmentLight {
public:
    // scale multiplies the map (RGB); domeToWorld may contain a uniform scale. Throws
    // opal::Error when scale is negative or scale times the map's largest value exceeds
    // kMaxEmittedRadiance.
    EnvironmentLight(std::shared_ptr<const LatLongMap> map, const Imath::M44d& domeToWorld, const Rgb& scale);
    // UsdLux: scale = color * intensity * 2^exposure, transform from the description.
    static EnvironmentLight fromDesc(std::shared_ptr<const LatLongMap> map, const hd::LightDesc& desc);

    // The radiance arriving from every texel of a cube map whose directions are in the
    // object space of a mesh placed by objectToWorld: texels x 3, area-averaged over each
    // texel (supersampled, weighted by solid angle).
    std::vector<float> cubeRadiance(const CubeMapLayout& cube, const Imath::M44d& objectToWorld) const;
    // The map alone (before scale) with the cube's directions in the dome's own frame:
    // unchanged by the dome's and the mesh's transforms and by its colour and intensity, so
    // that a rotation or a colour edit can reuse what is computed from it.
    std::vector<float> domeCubeMap(const CubeMapLayout& cube) const;
    // Row vectors: d_dome = d_object * domeFromObject(objectToWorld), a rotation.
    Imath::M33d domeFromObject(const Imath::M44d& objectToWorld) const;
    const Rgb& scale() const { return scale_; }
    const std::shared_ptr<const LatLongMap>& map() const { return map_; }

private:
    std::vector<float> cubeRadianceIn(const CubeMapLayout& cube, const Imath::M33d& domeFromCube, const Rgb& scale) const;

    std::shared_ptr<const LatLongMap> map_;
    Imath::M33d domeFromWorld_;
    Rgb scale_;
};

}  // namespace opal
