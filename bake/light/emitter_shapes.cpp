#include "bake/light/emitter_shapes.h"

#include "bake/mesh_import.h"
#include "bake/procedural_mesh.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>

namespace opal {
namespace {

constexpr int kSegments = 128;  // around +Y
constexpr int kRings = 64;      // pole to pole of the sphere

std::string rgbText(const Imath::V3f& c) {
    std::ostringstream text;
    text.precision(9);
    text << "radiance=" << c.x << "/" << c.y << "/" << c.z;
    return text.str();
}

std::string number(double v) {
    std::ostringstream text;
    text.precision(17);
    text << v;
    return text.str();
}

RenderMesh toRenderMesh(const ControlMesh& control) {
    RenderMesh mesh;
    mesh.points = control.positions;
    mesh.faceVertexCounts = control.faceVertexCounts;
    mesh.faceVertexIndices = control.faceVertexIndices;
    return mesh;
}

Emitter single(std::string kind, std::string description, RenderMesh mesh, const Imath::V3f& radiance) {
    Emitter e{kind, std::move(description), {}};
    e.parts.push_back({std::move(kind), std::move(mesh), frontFaceEmission(radiance)});
    return e;
}

std::uint64_t fileHash(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return xxh64(std::as_bytes(std::span(bytes.data(), bytes.size())));
}

}  // namespace

RenderMesh revolvedMesh(std::span<const Imath::V2f> profile, int segments, const std::string& name) {
    return toRenderMesh(makeSurfaceOfRevolution(profile, segments, name));
}

Emitter sphereEmitter(double radius, const Imath::V3f& radiance) {
    std::vector<Imath::V2f> profile;
    for (int i = 0; i <= kRings; ++i) {
        const double theta = std::numbers::pi * i / kRings;  // from the bottom pole
        const double x = i == 0 || i == kRings ? 0.0 : radius * std::sin(theta);
        profile.emplace_back(float(x), float(-radius * std::cos(theta)));
    }
    return single("sphere", "sphere:radius=" + number(radius) + "," + rgbText(radiance),
                  revolvedMesh(profile, kSegments, "sphere"), radiance);
}

Emitter diskEmitter(double radius, const Imath::V3f& radiance) {
    // A bottom cap: its fan faces -Y.
    const Imath::V2f profile[] = {{0.0f, 0.0f}, {float(radius), 0.0f}};
    return single("disk", "disk:radius=" + number(radius) + "," + rgbText(radiance),
                  revolvedMesh(profile, kSegments, "disk"), radiance);
}

Emitter rectangleEmitter(double width, double height, const Imath::V3f& radiance) {
    const float x = float(width / 2), z = float(height / 2);
    RenderMesh mesh;
    // Counter-clockwise seen from below (-Y).
    mesh.points = {{-x, 0.0f, -z}, {x, 0.0f, -z}, {x, 0.0f, z}, {-x, 0.0f, z}};
    mesh.faceVertexCounts = {4};
    mesh.faceVertexIndices = {0, 1, 2, 3};
    return single("rectangle", "rectangle:width=" + number(width) + ",height=" + number(height) + "," +
                                   rgbText(radiance),
                  std::move(mesh), radiance);
}

Emitter lampEmitter(const LampShape& s, const Imath::V3f& radiance) {
    for (double v : {s.radius, s.height, s.shadeRadius, s.shadeHeight})
        if (!(v > 0.0) || !std::isfinite(v)) throw Error("lamp: every size must be positive and finite");
    if (!(s.shadeRadius > s.radius))
        throw Error("lamp: shade_radius " + number(s.shadeRadius) + " mm must exceed the emitter's radius " +
                    number(s.radius) + " mm");
    const float r = float(s.radius), h = float(s.height / 2), R = float(s.shadeRadius), H = float(s.shadeHeight / 2);
    const Imath::V2f body[] = {{0.0f, -h}, {r, -h}, {r, h}, {0.0f, h}};
    const Imath::V2f shade[] = {{R, -H}, {R, H}};
    Emitter e{"lamp",
              "lamp:radius=" + number(s.radius) + ",height=" + number(s.height) + ",shade_radius=" +
                  number(s.shadeRadius) + ",shade_height=" + number(s.shadeHeight) + "," + rgbText(radiance),
              {}};
    e.parts.push_back({"emitter", revolvedMesh(body, kSegments, "lamp emitter"), frontFaceEmission(radiance)});
    e.parts.push_back({"shade", revolvedMesh(shade, kSegments, "lamp shade"), {}});
    return e;
}

Emitter meshEmitter(const std::filesystem::path& file, const Imath::V3f& radiance) {
    ImportedMesh imported = importMesh(file);
    std::ostringstream hash;
    hash << std::hex << fileHash(file);
    return single("mesh", "mesh:file=" + file.filename().string() + ",xxh64=" + hash.str() + "," + rgbText(radiance),
                  toRenderMesh(imported.mesh), radiance);
}

}  // namespace opal
