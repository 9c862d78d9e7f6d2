// Renders the incident radiance at a point as a cube map (schema/asset/cube_map.h layout):
// each texel holds the mean radiance of stratified rays through its face square (one
// jittered ray per stratum), traced from the point against the emitter. First 2 x 2
// rays per texel; a texel that may hold an edge of a part's image (its rays do not all
// see the same thing, one part or nothing; or a neighbour on its face saw something else;
// or it borders its face) is traced again with k x k rays, and holds their mean. Texels
// well inside one part's image, or well outside the emitter, keep the 2 x 2 mean. A texel
// whose cone (centre direction plus the angle to its farthest corner) misses the cone
// the emitter's bounding sphere subtends from the point cannot see the emitter: it is
// black without tracing. Deterministic: the jitter comes from the caller's Random.
#pragma once

#include "bake/light/emitter_scene.h"
#include "bake/random.h"
#include "schema/asset/cube_map.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class IncidentRadianceRenderer {
public:
    IncidentRadianceRenderer(const EmitterScene& scene, std::uint32_t mapFaceSize, std::uint32_t raysPerSide);

    const CubeMapLayout& layout() const { return layout_; }
    // 3 floats (RGB) per texel, texel-major. Adds the rays traced to *rays when given.
    std::vector<float> render(const Imath::V3f& point, Random& random, std::uint64_t* rays = nullptr) const;

private:
    static constexpr std::uint32_t kFirstPassSide = 2;
    void addRays(const Imath::V3f& point, std::uint32_t texel, std::uint32_t k, Random& random,
                 std::vector<Ray>& rays) const;
    static constexpr std::int64_t kNothing = -1, kMixed = -2;
    void trace(std::span<const std::uint32_t> texels, std::span<const Ray> rays, std::uint32_t perTexel,
               std::vector<float>& rgb, std::vector<std::int64_t>& seen) const;
    bool mayHoldEdge(std::uint32_t texel, const std::vector<std::int64_t>& seen) const;
    std::vector<std::uint32_t> candidateTexels(const Imath::V3f& point) const;

    const EmitterScene& scene_;
    CubeMapLayout layout_;
    std::uint32_t raysPerSide_;
    std::vector<Imath::V3f> centres_;
    std::vector<float> halfAngles_;  // centre to farthest corner, radians
};

}  // namespace opal
