#include "schema/asset/point_range.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace opal {

void checkPointRange(std::span<const Imath::V3f> points, double unitsPerMm, std::string_view context,
                     std::string_view what) {
    const double limit = kMaxDistanceMm * unitsPerMm;  // in the asset's units
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Imath::V3f& p = points[i];
        const double largest = std::max({std::abs(double(p.x)), std::abs(double(p.y)), std::abs(double(p.z))});
        if (largest <= limit) continue;  // false for NaN
        std::ostringstream s;
        s << context << ": " << what << " " << i << " (" << p.x << ", " << p.y << ", " << p.z << ") ";
        if (!std::isfinite(largest))
            s << "is not finite";
        else
            s << "lies " << largest / unitsPerMm << " mm from the origin, beyond the 1e9 mm (1,000 km) an asset may span";
        throw Error(s.str());
    }
}

}  // namespace opal
