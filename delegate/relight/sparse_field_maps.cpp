#include "delegate/relight/sparse_field_maps.h"

#include <tbb/parallel_for.h>

namespace opal {

SparseFieldMaps::SparseFieldMaps(const ShadowFieldLookup& lookup, std::uint32_t faceSize) {
    const std::size_t maps = lookup.field().offsets.size() - 1;
    struct Sparse {
        std::vector<std::uint32_t> texels;
        std::vector<Float4> terms;
    };
    std::vector<Sparse> each(maps);
    offsets_.push_back(0);
    if (maps == 0) return;
    (void)lookup.mapTerms(0, faceSize);  // a bad face size throws here, not inside the workers
    tbb::parallel_for(std::size_t(0), maps, [&](std::size_t m) {
        const std::vector<Imath::V3f> terms = lookup.mapTerms(m, faceSize);
        for (std::uint32_t k = 0; k < terms.size(); ++k) {
            if (terms[k] == Imath::V3f(0.0f)) continue;
            each[m].texels.push_back(k);
            each[m].terms.push_back(Float4{terms[k].x, terms[k].y, terms[k].z, 0.0f});
        }
    });
    offsets_.reserve(maps + 1);
    for (Sparse& s : each) {
        texels_.insert(texels_.end(), s.texels.begin(), s.texels.end());
        terms_.insert(terms_.end(), s.terms.begin(), s.terms.end());
        offsets_.push_back(texels_.size());
        s = {};
    }
}

std::span<const std::uint32_t> SparseFieldMaps::texels(std::uint64_t index) const {
    return {texels_.data() + offsets_[index], texels_.data() + offsets_[index + 1]};
}

std::span<const Float4> SparseFieldMaps::terms(std::uint64_t index) const {
    return {terms_.data() + offsets_[index], terms_.data() + offsets_[index + 1]};
}

}  // namespace opal
