// The light spec syntax of `opal-bake light`: each kind builds its emitter, and every bad
// spec is refused naming the spec and the problem.
#include "bake/light/light_spec.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace opal {
namespace {

std::string errorOf(std::string_view spec) {
    try {
        parseLightSpec(spec);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(LightSpec, EachKindBuildsItsEmitter) {
    EXPECT_EQ(parseLightSpec("sphere:radius=5").kind, "sphere");
    EXPECT_EQ(parseLightSpec("disk:radius=2,radiance=3").kind, "disk");
    EXPECT_EQ(parseLightSpec("rectangle:width=4,height=2,radiance=1/2/3").kind, "rectangle");
    const Emitter lamp = parseLightSpec("lamp:radius=2,height=5");
    EXPECT_EQ(lamp.parts.size(), 2u);
    EXPECT_FALSE(lamp.parts[1].emission);  // the shade emits nothing
    EXPECT_EQ(parseLightSpec("flame:height=20,radius=4,core_k=2600").kind, "flame");
    // Different parameters, different descriptions (they enter the bake identifier).
    EXPECT_NE(parseLightSpec("sphere:radius=5").description, parseLightSpec("sphere:radius=5,radiance=2").description);
    EXPECT_EQ(parseLightSpec("sphere:radius=5").description, parseLightSpec("sphere:radius=5.0,radiance=1").description);
}

// An emitter from a file: its polygons as read, emitting from their front faces.
TEST(LightSpec, MeshEmitterReadsItsFile) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("opal-light-spec-" + std::to_string(::getpid()) + ".obj");
    {
        std::ofstream out(file);
        out << "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n";  // counter-clockwise seen from -Y
    }
    const Emitter e = parseLightSpec("mesh:file=" + file.string() + ",radiance=2");
    std::filesystem::remove(file);
    EXPECT_EQ(e.kind, "mesh");
    ASSERT_EQ(e.parts.size(), 1u);
    EXPECT_EQ(e.parts[0].mesh.points.size(), 4u);
    EXPECT_EQ(e.parts[0].mesh.faceVertexCounts, std::vector<std::int32_t>{4});
    const Imath::V3f down(0, -1, 0);
    EXPECT_EQ(e.parts[0].emission({{0.5f, 0, 0.5f}, -down, down}), Imath::V3f(2.0f));
}

TEST(LightSpec, RadianceIsGreyOrRgb) {
    const Emitter e = parseLightSpec("rectangle:width=4,height=2,radiance=1/2/3");
    const Imath::V3f seen = e.parts[0].emission({{0, 0, 0}, {0, 1, 0}, {0, -1, 0}});
    EXPECT_EQ(seen, Imath::V3f(1, 2, 3));
}

TEST(LightSpec, BadSpecsNameTheProblem) {
    const struct {
        const char* spec;
        const char* problem;
    } cases[] = {
        {"", "unknown kind ''"},
        {"candle:radius=1", "unknown kind 'candle' (kinds: sphere, disk, rectangle, lamp, mesh, flame)"},
        {"sphere", "expected KIND:KEY=VALUE"},
        {"sphere:", "'' is not KEY=VALUE"},
        {"sphere:radius", "'radius' is not KEY=VALUE"},
        {"sphere:radius=", "'radius=' is not KEY=VALUE"},
        {"sphere:radius=5,", "'' is not KEY=VALUE"},
        {"sphere:diameter=5", "unknown key 'diameter' for sphere (keys: radius, radiance)"},
        {"sphere:radius=5,radius=6", "key 'radius' given twice"},
        {"sphere:radiance=2", "missing radius="},
        {"sphere:radius=five", "radius=five is not a finite number"},
        {"sphere:radius=5mm", "radius=5mm is not a finite number"},
        {"sphere:radius=inf", "radius=inf is not a finite number"},
        {"sphere:radius=0", "radius=0 must be positive"},
        {"sphere:radius=1,radiance=-1", "radiance=-1 must not be negative"},
        {"sphere:radius=1,radiance=1/2", "radiance=1/2 must be L or R/G/B"},
        {"lamp:radius=5,height=2,shade_radius=4", "shade_radius must exceed radius"},
        {"flame:height=20,radius=4,core_k=90000", "colour temperatures must be within 500 to 40000 K"},
        {"mesh:file=/nonexistent/lamp.obj", "/nonexistent/lamp.obj"},
    };
    for (const auto& c : cases) {
        const std::string error = errorOf(c.spec);
        EXPECT_NE(error.find("light spec '" + std::string(c.spec) + "'"), std::string::npos) << error;
        EXPECT_NE(error.find(c.problem), std::string::npos) << c.spec << " -> " << error;
    }
}

}  // namespace
}  // namespace opal
