#include "bake/mesh_import.h"

#include "bake/mesh_validation.h"
#include "schema/error.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace opal {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Each face as its corner positions, to compare meshes whose vertex numbering differs.
std::vector<std::vector<Imath::V3f>> facePositions(const std::vector<Imath::V3f>& positions,
                                                   const std::vector<std::int32_t>& counts,
                                                   const std::vector<std::int32_t>& indices) {
    std::vector<std::vector<Imath::V3f>> faces;
    std::size_t start = 0;
    for (std::int32_t n : counts) {
        std::vector<Imath::V3f> face;
        for (std::int32_t c = 0; c < n; ++c) face.push_back(positions[indices[start + c]]);
        faces.push_back(face);
        start += std::size_t(n);
    }
    return faces;
}

std::vector<std::vector<Imath::V3f>> facePositions(const ControlMesh& m) {
    return facePositions(m.positions, m.faceVertexCounts, m.faceVertexIndices);
}

class MeshImport : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("opal-mesh-import-" + std::to_string(::getpid()) + "-" + info->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const std::string& contents) {
        fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << contents;
        return path;
    }

    // Imports and validates, returning the mesh and all warnings.
    std::pair<ControlMesh, std::vector<std::string>> importAndRepair(const fs::path& path) {
        ImportedMesh imported = importMesh(path);
        ValidationReport report = validateAndRepair(imported.mesh);
        std::vector<std::string> warnings = imported.warnings;
        warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
        return {imported.mesh, warnings};
    }

    std::string errorOf(const fs::path& path) {
        try {
            importMesh(path);
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    }

    fs::path dir_;
};

std::string cubeObjWithSeamedUvs() {
    ControlMesh cube = test::cube();
    std::ostringstream obj;
    obj << "# a cube, every face with its own UVs\n";
    for (const Imath::V3f& p : cube.positions) obj << "v " << p.x << " " << p.y << " " << p.z << "\n";
    obj << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    for (std::size_t f = 0; f < 6; ++f) {
        obj << (f == 3 ? "g second_group\nf" : "f");
        for (int c = 0; c < 4; ++c) obj << " " << cube.faceVertexIndices[4 * f + c] + 1 << "/" << c + 1;
        obj << "\n";
    }
    return obj.str();
}

TEST_F(MeshImport, ObjKeepsQuadsAndFaceVaryingUvs) {
    auto [mesh, warnings] = importAndRepair(write("cube.obj", cubeObjWithSeamedUvs()));
    // The reader splits vertices at UV seams (how many depends on its own joining).
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(contains(warnings[0], "vertices with identical positions")) << warnings[0];
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.faceVertexCounts, std::vector<std::int32_t>(6, 4));
    EXPECT_EQ(facePositions(mesh), facePositions(test::cube()));
    ASSERT_TRUE(mesh.hasUvs());
    ASSERT_EQ(mesh.uvIndices.size(), 24u);
    const Imath::V2f expected[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (std::size_t c = 0; c < 24; ++c) EXPECT_EQ(mesh.uvs[mesh.uvIndices[c]], expected[c % 4]) << "corner " << c;
    EXPECT_TRUE(contains(mesh.source, "cube.obj"));
}

TEST_F(MeshImport, PlyKeepsPolygons) {
    ControlMesh cube = test::cube();
    std::ostringstream ply;
    ply << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Imath::V3f& p : cube.positions) ply << p.x << " " << p.y << " " << p.z << "\n";
    for (std::size_t f = 0; f < 6; ++f) {
        ply << "4";
        for (int c = 0; c < 4; ++c) ply << " " << cube.faceVertexIndices[4 * f + c];
        ply << "\n";
    }
    auto [mesh, warnings] = importAndRepair(write("cube.PLY", ply.str()));
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(facePositions(mesh), facePositions(cube));
    EXPECT_FALSE(mesh.hasUvs());
}

std::string asciiStl(const ControlMesh& triangles) {
    std::ostringstream stl;
    stl << "solid octahedron\n";
    for (std::size_t f = 0; f < triangles.faceCount(); ++f) {
        stl << " facet normal 0 0 0\n  outer loop\n";
        for (int c = 0; c < 3; ++c) {
            const Imath::V3f& p = triangles.positions[triangles.faceVertexIndices[3 * f + c]];
            stl << "   vertex " << p.x << " " << p.y << " " << p.z << "\n";
        }
        stl << "  endloop\n endfacet\n";
    }
    stl << "endsolid octahedron\n";
    return stl.str();
}

std::string binaryStl(const ControlMesh& triangles) {
    std::string stl(80, ' ');
    std::memcpy(stl.data(), "binary test", 11);
    auto putU32 = [&](std::uint32_t x) {
        for (int i = 0; i < 4; ++i) stl += char((x >> (8 * i)) & 0xff);
    };
    auto putF32 = [&](float x) {
        std::uint32_t bits;
        std::memcpy(&bits, &x, 4);
        putU32(bits);
    };
    putU32(std::uint32_t(triangles.faceCount()));
    for (std::size_t f = 0; f < triangles.faceCount(); ++f) {
        for (int i = 0; i < 3; ++i) putF32(0.0f);
        for (int c = 0; c < 3; ++c) {
            const Imath::V3f& p = triangles.positions[triangles.faceVertexIndices[3 * f + c]];
            putF32(p.x);
            putF32(p.y);
            putF32(p.z);
        }
        stl += std::string(2, '\0');
    }
    return stl;
}

TEST_F(MeshImport, AsciiAndBinaryStlWeldIntoAClosedMesh) {
    ControlMesh octa = test::octahedron();
    for (const auto& [name, contents] : {std::pair{"octa.stl", asciiStl(octa)}, std::pair{"octa-bin.stl", binaryStl(octa)}}) {
        auto [mesh, warnings] = importAndRepair(write(name, contents));
        // STL repeats every corner; the reader may join some, the repair welds the rest.
        ASSERT_LE(warnings.size(), 1u) << name;
        if (!warnings.empty()) {
            EXPECT_TRUE(contains(warnings[0], "vertices with identical positions")) << warnings[0];
        }
        EXPECT_EQ(mesh.positions.size(), 6u) << name;
        EXPECT_EQ(facePositions(mesh), facePositions(octa)) << name;
    }
}

// A glTF with an external buffer: the octahedron, placed by a mirroring node transform.
TEST_F(MeshImport, GltfAppliesNodeTransformsAndKeepsWindingUnderMirroring) {
    ControlMesh octa = test::octahedron();
    std::string buffer;
    for (const Imath::V3f& p : octa.positions) buffer.append(reinterpret_cast<const char*>(&p), 12);
    for (std::int32_t i : octa.faceVertexIndices) {
        auto index = std::uint16_t(i);
        buffer.append(reinterpret_cast<const char*>(&index), 2);
    }
    write("octa.bin", buffer);
    std::string gltf = R"({
      "asset": {"version": "2.0"},
      "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0, "translation": [10, 0, 0], "scale": [-1, 1, 1]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"byteLength": 120, "uri": "octa.bin"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 72},
                      {"buffer": 0, "byteOffset": 72, "byteLength": 48}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                     "min": [-1, -1, -1], "max": [1, 1, 1]},
                    {"bufferView": 1, "componentType": 5123, "count": 24, "type": "SCALAR"}]
    })";
    auto [mesh, warnings] = importAndRepair(write("octa.gltf", gltf));
    // No "inside out" warning: the mirrored faces were re-wound on import.
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(mesh.positions.size(), 6u);
    for (std::size_t v = 0; v < 6; ++v) {
        Imath::V3f expected = octa.positions[v];
        expected.x = 10.0f - expected.x;
        EXPECT_TRUE(std::find(mesh.positions.begin(), mesh.positions.end(), expected) != mesh.positions.end()) << v;
    }
}

TEST_F(MeshImport, RefusesMissingFileAndUnknownFormat) {
    fs::path missing = dir_ / "nowhere.obj";
    EXPECT_EQ(errorOf(missing), missing.string() + ": no such file");
    fs::path xyz = write("points.xyz", "0 0 0\n");
    EXPECT_EQ(errorOf(xyz), xyz.string() + ": unsupported mesh format '.xyz'; supported: .obj .ply .gltf .glb .stl .usda");
    EXPECT_TRUE(contains(errorOf(dir_), "not a regular file"));
}

TEST_F(MeshImport, RefusesFilesWithoutPolygons) {
    fs::path points = write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    std::string error = errorOf(points);
    EXPECT_TRUE(contains(error, points.string() + ": ")) << error;
    fs::path garbage = write("garbage.ply", "this is not a mesh\n");
    error = errorOf(garbage);
    EXPECT_TRUE(contains(error, garbage.string() + ": ")) << error;
}

TEST_F(MeshImport, RefusesTruncatedFiles) {
    std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n";  // 2 of the 4 faces
    fs::path path = write("truncated.ply", ply);
    std::string error = errorOf(path);
    EXPECT_EQ(error, path.string() + ": the file is truncated or malformed: the header declares 8 elements but only 6 "
                                     "data lines follow");

    std::string stl = binaryStl(test::octahedron());
    stl.resize(stl.size() - 50 * 3);  // 3 triangles missing: no longer a consistent binary STL
    path = write("truncated.stl", stl);
    error = errorOf(path);
    EXPECT_EQ(error, path.string() + ": the file is truncated or malformed: the binary header declares 8 triangles "
                                     "(484 bytes) but the file has 334 bytes");
}

TEST_F(MeshImport, SkipsLinesWithAWarning) {
    std::string obj = cubeObjWithSeamedUvs() + "l 1 8\n";
    ImportedMesh imported = importMesh(write("cube-with-line.obj", obj));
    ASSERT_EQ(imported.warnings.size(), 1u);
    EXPECT_EQ(imported.warnings[0], "skipped 1 point and line primitives (only polygons are subdivided)");
    EXPECT_EQ(imported.mesh.faceCount(), 6u);
}

}  // namespace
}  // namespace opal
