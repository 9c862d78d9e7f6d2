// The USDA text test scenes are written in (what the scene reader reads): a layer header
// in millimetres, an asset referenced and placed, a point
// light, a camera with UsdGeomCamera's 36 x 24 mm film and 50 mm lens, and a render
// resolution. Each prim ends with a blank line, so that prims concatenate into a layer.
// A translate is a still value (translate) or time samples (translateSamples).
#pragma once

#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace opal::test::usda {

struct Point {
    double x = 0.0, y = 0.0, z = 0.0;
};

// "(x, y, z)" with C++'s default six significant digits: (0.6, 80, 20).
inline std::string tuple(const Point& p) {
    std::ostringstream out;
    out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
    return out.str();
}

// The translate and its xformOpOrder, as the body lines of a prim.
inline std::string translate(const Point& p) {
    return "    double3 xformOp:translate = " + tuple(p) + "\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n";
}

inline std::string translateSamples(const std::vector<std::pair<double, Point>>& samples) {
    std::ostringstream out;
    out << "    double3 xformOp:translate.timeSamples = {\n";
    for (const auto& [time, p] : samples) out << "        " << time << ": " << tuple(p) << ",\n";
    out << "    }\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n";
    return out.str();
}

// "#usda 1.0" with metersPerUnit 0.001 and any further layer metadata lines.
inline std::string header(const std::string& metadata = {}) {
    return "#usda 1.0\n(\n    metersPerUnit = 0.001\n" + metadata + ")\n\n";
}

// def "name" (references = @file@) with an optional translate.
inline std::string reference(const std::string& name, const std::string& file, const std::string& body = {}) {
    return "def \"" + name + "\" (\n    references = @" + file + "@\n)\n{\n" + body + "}\n\n";
}

// A SphereLight treated as a point.
inline std::string pointLight(const std::string& name, const std::string& intensity, const std::string& placement) {
    return "def SphereLight \"" + name + "\"\n{\n    float inputs:intensity = " + intensity +
           "\n    bool treatAsPoint = 1\n" + placement + "}\n\n";
}

inline std::string camera(const std::string& name, const std::string& placement) {
    return "def Camera \"" + name +
           "\"\n{\n    float focalLength = 50\n    float horizontalAperture = 36\n    float verticalAperture = 24\n" +
           placement + "}\n\n";
}

inline std::string renderSettings(int width, int height) {
    return "def RenderSettings \"Settings\"\n{\n    uniform int2 resolution = (" + std::to_string(width) + ", " +
           std::to_string(height) + ")\n}\n";
}

}  // namespace opal::test::usda
