// The light prim types, UsdLux's and Opal's shadow-field light: every delegate that lights
// supports them all (the preview too, which keeps lights only so that a lit scene
// populates), in this order among its supported Sprim types.
#pragma once

#include "delegate/hd/types.h"

#include <algorithm>
#include <vector>

namespace opal::hd {

inline const std::vector<Token>& lightPrimTypes() {
    static const std::vector<Token> types = {PrimType::SphereLight, PrimType::DistantLight, PrimType::DomeLight,
                                             PrimType::ShadowFieldLight};
    return types;
}

inline bool isLightPrimType(const Token& type) {
    return std::find(lightPrimTypes().begin(), lightPrimTypes().end(), type) != lightPrimTypes().end();
}

}  // namespace opal::hd
