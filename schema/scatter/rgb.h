// Per-channel quantities (scattering coefficients, albedo, radiance) are RGB triples in the
// working color space (ACEScg unless the OCIO config says otherwise).
#pragma once

#include <Imath/ImathColor.h>

namespace opal {

using Rgb = Imath::Color3<double>;

}  // namespace opal
