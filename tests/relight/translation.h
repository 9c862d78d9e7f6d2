// The translation by (x, y, z), as an Imath matrix (row vectors: p * m).
#pragma once

#include <Imath/ImathMatrix.h>

namespace opal::test {

inline Imath::M44d translation(double x, double y, double z) {
    Imath::M44d m;
    m.setTranslation(Imath::V3d(x, y, z));
    return m;
}

}  // namespace opal::test
