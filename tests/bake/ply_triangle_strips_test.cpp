// PLY triangle strips: the decoder against the convention written out by hand, and whole
// files (ASCII, binary little and big endian) against the same mesh written as faces and
// read by Assimp; a strip file bakes like any mesh; malformed strip files and implausible
// meshes are refused with the file and the reason.
#include "bake/bake_pipeline.h"
#include "bake/mesh_import.h"
#include "bake/ply_triangle_strips.h"
#include "schema/error.h"
#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>

namespace opal {
namespace {

using test::ScratchDir;

// ---- the decoder ----------------------------------------------------------------------

TEST(TriangleStripDecoding, AlternatesWindingSkipsRepeatedVerticesAndRestartsAtMinusOne) {
    StripTriangles out;
    const std::vector<std::int32_t> strip = {0, 1, 2, 3, 4, -1, 5, 6, 7, 7, 8, 9, -1, 10, 11};
    decodeTriangleStrip(strip, out);
    // Triangle k of a run is (v_k, v_k+1, v_k+2) for even k, (v_k+1, v_k, v_k+2) for odd k.
    const std::vector<std::int32_t> expected = {
        0, 1, 2,  2, 1, 3,  2, 3, 4,  // the first run
        5, 6, 7,                      // k = 1 (6 7 7) and k = 2 (7 7 8) repeat a vertex
        8, 7, 9,                      // k = 3 is odd
    };                                // the last run has two vertices: no triangle
    EXPECT_EQ(out.corners, expected);
    EXPECT_EQ(out.degenerate, 2u);
}

// ---- a sphere as strips and as faces --------------------------------------------------

// A UV sphere of radius 20: a pole, rings, a pole. Every latitude band is one strip.
struct StripSphere {
    std::vector<Imath::V3f> points;
    std::vector<std::vector<std::int32_t>> strips;  // one per band, each closed around
    std::vector<std::array<std::int32_t, 3>> triangles;  // the same surface, outward

    static constexpr int kBands = 6, kSegments = 8;
};

Imath::V3d at(const StripSphere& s, std::int32_t i) { return Imath::V3d(s.points[std::size_t(i)]); }

bool outward(const StripSphere& s, std::int32_t a, std::int32_t b, std::int32_t c) {
    const Imath::V3d n = (at(s, b) - at(s, a)).cross(at(s, c) - at(s, a));
    return n.dot(at(s, a) + at(s, b) + at(s, c)) > 0.0;
}

// The band between rings a and b (a pole is a ring of one repeated vertex) as a strip
// a0 b0 a1 b1 ... a0 b0, whose triangles are (a_j, b_j, a_j+1) and, odd, (a_j+1, b_j, b_j+1).
// Reversed (b first) when those face inward.
void addBand(StripSphere& s, const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
    const bool flip = !outward(s, a[1], b[0], b[1]);
    const auto& first = flip ? b : a;
    const auto& second = flip ? a : b;
    std::vector<std::int32_t> strip;
    for (std::size_t j = 0; j <= a.size(); ++j) {
        strip.push_back(first[j % a.size()]);
        strip.push_back(second[j % a.size()]);
    }
    s.strips.push_back(strip);
    for (std::size_t j = 0; j < a.size(); ++j) {  // the band's quads, split as the strip does, made outward
        const std::size_t k = (j + 1) % a.size();
        for (std::array<std::int32_t, 3> t :
             {std::array{first[j], second[j], first[k]}, std::array{first[k], second[j], second[k]}}) {
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
            if (!outward(s, t[0], t[1], t[2])) std::swap(t[1], t[2]);
            s.triangles.push_back(t);
        }
    }
}

StripSphere stripSphere() {
    StripSphere s;
    const double pi = std::numbers::pi;
    std::vector<std::vector<std::int32_t>> rings;
    s.points.emplace_back(0.0f, 20.0f, 0.0f);
    rings.push_back(std::vector<std::int32_t>(StripSphere::kSegments, 0));
    for (int i = 1; i < StripSphere::kBands; ++i) {
        std::vector<std::int32_t> ring;
        const double theta = pi * i / StripSphere::kBands;
        for (int j = 0; j < StripSphere::kSegments; ++j) {
            const double phi = 2.0 * pi * j / StripSphere::kSegments;
            ring.push_back(std::int32_t(s.points.size()));
            s.points.emplace_back(float(20 * std::sin(theta) * std::cos(phi)), float(20 * std::cos(theta)),
                                  float(20 * std::sin(theta) * std::sin(phi)));
        }
        rings.push_back(ring);
    }
    s.points.emplace_back(0.0f, -20.0f, 0.0f);
    rings.push_back(std::vector<std::int32_t>(StripSphere::kSegments, std::int32_t(s.points.size() - 1)));
    for (std::size_t r = 0; r + 1 < rings.size(); ++r) addBand(s, rings[r], rings[r + 1]);
    return s;
}

std::string header(const std::string& format, std::size_t vertices, const std::string& extraVertexProperty,
                   const std::string& elements) {
    std::ostringstream h;
    h << "ply\nformat " << format << " 1.0\ncomment made by ply_triangle_strips_test\nelement vertex " << vertices
      << "\nproperty float x\nproperty float y\nproperty float z\n"
      << extraVertexProperty << elements << "end_header\n";
    return h.str();
}

std::string asciiFaces(const StripSphere& s) {
    std::ostringstream out;
    out << header("ascii", s.points.size(), "", "element face " + std::to_string(s.triangles.size()) +
                                                     "\nproperty list uchar int vertex_indices\n");
    out.precision(9);
    for (const Imath::V3f& p : s.points) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return out.str();
}

// All strips in one record joined by -1, as the classic scans store them.
std::vector<std::int32_t> joined(const StripSphere& s) {
    std::vector<std::int32_t> all;
    for (const auto& strip : s.strips) {
        if (!all.empty()) all.push_back(-1);
        all.insert(all.end(), strip.begin(), strip.end());
    }
    return all;
}

std::string asciiStrips(const StripSphere& s) {
    std::ostringstream out;
    out << header("ascii", s.points.size(), "", "element tristrips 1\nproperty list int int vertex_indices\n");
    out.precision(9);
    for (const Imath::V3f& p : s.points) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    const std::vector<std::int32_t> all = joined(s);
    out << all.size();
    for (std::int32_t i : all) out << ' ' << i;
    out << '\n';
    return out.str();
}

// Appends a value's bytes in the chosen byte order.
template <typename T>
void put(std::string& out, T value, bool bigEndian) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

// Little endian: a uchar per vertex to skip, one record per band with a ushort length.
// Big endian: a float per vertex to skip, one record for everything (the Igea layout).
std::string binaryStrips(const StripSphere& s, bool bigEndian) {
    std::string out = bigEndian
        ? header("binary_big_endian", s.points.size(), "property float confidence\n",
                 "element tristrips 1\nproperty list int int vertex_indices\n")
        : header("binary_little_endian", s.points.size(), "property uchar quality\n",
                 "element tristrips " + std::to_string(s.strips.size()) + "\nproperty list ushort int vertex_indices\n");
    for (const Imath::V3f& p : s.points) {
        put(out, p.x, bigEndian), put(out, p.y, bigEndian), put(out, p.z, bigEndian);
        bigEndian ? put(out, 0.5f, true) : put(out, std::uint8_t(200), false);
    }
    const std::vector<std::vector<std::int32_t>> records =
        bigEndian ? std::vector<std::vector<std::int32_t>>{joined(s)} : s.strips;
    for (const auto& record : records) {
        bigEndian ? put(out, std::int32_t(record.size()), true) : put(out, std::uint16_t(record.size()), false);
        for (std::int32_t i : record) put(out, i, bigEndian);
    }
    return out;
}

// Each face as its corner positions rotated to start at the smallest, sorted: the same
// oriented surface gives the same list whatever the vertex numbering.
using Corners = std::vector<std::array<float, 3>>;
std::vector<Corners> orientedFaces(const ControlMesh& m) {
    std::vector<Corners> faces;
    std::size_t start = 0;
    for (std::int32_t n : m.faceVertexCounts) {
        Corners face;
        for (std::int32_t c = 0; c < n; ++c) {
            const Imath::V3f& p = m.positions[std::size_t(m.faceVertexIndices[start + std::size_t(c)])];
            face.push_back({p.x, p.y, p.z});
        }
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        faces.push_back(face);
        start += std::size_t(n);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

TEST(PlyTriangleStrips, AsciiAndBinaryStripsReadAsTheSameMeshWrittenAsFaces) {
    const StripSphere sphere = stripSphere();
    ASSERT_EQ(sphere.triangles.size(), std::size_t(2 * StripSphere::kSegments * (StripSphere::kBands - 1)));
    const ScratchDir dir;
    test::writeText(dir / "faces.ply", asciiFaces(sphere));
    const ImportedMesh faces = importMesh(dir / "faces.ply");  // Assimp's face path
    ASSERT_EQ(faces.mesh.faceCount(), sphere.triangles.size());
    const std::vector<Corners> truth = orientedFaces(faces.mesh);

    const std::vector<std::pair<std::string, std::string>> files = {
        {"ascii.ply", asciiStrips(sphere)},
        {"little.ply", binaryStrips(sphere, false)},
        {"big.ply", binaryStrips(sphere, true)},
    };
    for (const auto& [name, contents] : files) {
        SCOPED_TRACE(name);
        test::writeText(dir / name, contents);
        const ImportedMesh strips = importMesh(dir / name);
        EXPECT_EQ(strips.mesh.positions.size(), sphere.points.size());
        EXPECT_EQ(orientedFaces(strips.mesh), truth);
    }
}

TEST(PlyTriangleStrips, AStripFileBakesLikeTheSameMeshWrittenAsFaces) {
    const StripSphere sphere = stripSphere();
    const ScratchDir dir;
    test::writeText(dir / "faces.ply", asciiFaces(sphere));
    test::writeText(dir / "strips.ply", binaryStrips(sphere, true));
    const auto bake = [](const std::filesystem::path& input) {
        BakeOptions options;
        options.input = input.string();
        options.level = 1;
        options.samples = 256;
        options.visibility.cubeFaceSize = 8;
        options.visibility.terms = 16;
        return bakeAsset(options, nullptr, CancelToken{}, nullptr);
    };
    const TranslucentAsset fromStrips = bake(dir / "strips.ply");
    const TranslucentAsset fromFaces = bake(dir / "faces.ply");
    ASSERT_EQ(fromStrips.samples.size(), 256u);
    ASSERT_EQ(fromFaces.samples.size(), 256u);
    double stripArea = 0.0, faceArea = 0.0;
    for (const SurfaceSample& s : fromStrips.samples) stripArea += s.area;
    for (const SurfaceSample& s : fromFaces.samples) faceArea += s.area;
    EXPECT_NEAR(stripArea, faceArea, 1e-4 * faceArea);
    EXPECT_EQ(fromStrips.mesh.points.size(), fromFaces.mesh.points.size());
    for (double v : fromStrips.basis.values()) ASSERT_TRUE(std::isfinite(v));
}

// ---- refusals -------------------------------------------------------------------------

std::string importError(const std::filesystem::path& path) {
    try {
        importMesh(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

void expectMentions(const std::string& error, std::initializer_list<std::string> parts) {
    EXPECT_FALSE(error.empty()) << "no error";
    for (const std::string& part : parts) EXPECT_NE(error.find(part), std::string::npos) << error << "\nlacks: " << part;
}

const std::string kFourVertices = "0 0 0\n1 0 0\n0 1 0\n1 1 1\n";

std::string stripFile(const std::string& elements, const std::string& data) {
    return header("ascii", 4, "", elements) + kFourVertices + data;
}

std::string littleInts(std::initializer_list<std::int32_t> values) {
    std::string out;
    for (std::int32_t v : values) put(out, v, false);
    return out;
}

TEST(PlyTriangleStrips, MalformedStripFilesNameTheFileElementAndItem) {
    const ScratchDir dir;
    const std::string strips = "element tristrips 1\nproperty list int int vertex_indices\n";
    const struct {
        std::string name, contents;
        std::initializer_list<std::string> expected;
    } cases[] = {
        {"short.ply", stripFile(strips, "5 0 1 -1 2 3\n"), {"short.ply", "triangle strips", "no strip holds a triangle"}},
        {"range.ply", stripFile(strips, "4 0 1 2 9\n"), {"range.ply", "element 'tristrips' 0", "item 3 is 9", "4)"}},
        {"negative.ply", stripFile(strips, "4 0 1 2 -2\n"), {"negative.ply", "item 3 is -2", "-1 (a restart)"}},
        {"text.ply", stripFile(strips, "4 0 1 x 3\n"), {"text.ply", "element 'tristrips' 0", "'x' is not an integer"}},
        {"ends.ply", stripFile(strips, "4 0 1 2\n"), {"ends.ply", "element 'tristrips' 0", "ends early"}},
        {"nolist.ply", stripFile("element tristrips 1\nproperty int a\n", "7\n"), {"nolist.ply", "'vertex_indices'"}},
        {"format.ply", "ply\nformat ebcdic 1.0\nelement vertex 0\nelement tristrips 1\nend_header\n",
         {"format.ply:2:", "unknown format 'ebcdic'"}},
        {"huge.ply", header("binary_little_endian", 4000000000u, "", strips) + std::string(64, '\0'),
         {"huge.ply", "'element vertex 4000000000'"}},
        // 2^64 - 1 records of nothing (binary: no line count for the census to check).
        {"empty.ply", header("binary_little_endian", 4, "", "element nothing 18446744073709551615\n" + strips) +
                          std::string(48, '\0') + littleInts({2, 0, 1}),
         {"empty.ply", "no strip holds a triangle"}},
        // 2^63 records of two bytes: a size that wraps to 0 in 64 bits.
        {"wrap.ply",
         header("binary_little_endian", 1, "", "element pairs 9223372036854775808\nproperty uchar a\nproperty uchar b\n" +
                strips) + std::string(12, '\0'),
         {"wrap.ply", "'element pairs 9223372036854775808' declares more data than the file holds"}},
        {"long.ply", header("binary_little_endian", 1, "", strips) + std::string(12, '\0') + "\xff\xff\xff\x7f",
         {"long.ply", "element 'tristrips' 0", "list length of 2147483647"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        test::writeText(dir / c.name, c.contents);
        expectMentions(importError(dir / c.name), c.expected);
    }
}

TEST(MeshImportPlausibility, ACountNearTwoToThe64DoesNotHideATruncatedAsciiFile) {
    // 4 vertices + 1 face + (2^64 - 5) others wrap to 0 declared elements in 64 bits.
    const ScratchDir dir;
    test::writeText(dir / "wrap.ply", header("ascii", 4, "", "element face 1\nproperty list uchar int vertex_indices\n"
                                                             "element other 18446744073709551611\nproperty uchar a\n") +
                                          kFourVertices + "3 0 1 2\n");
    expectMentions(importError(dir / "wrap.ply"), {"wrap.ply", "truncated or malformed"});
}

TEST(MeshImportPlausibility, AMeshWithZeroAreaIsRefusedWithTheFile) {
    const ScratchDir dir;
    test::writeText(dir / "flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3\nf 2 3 4\n");
    expectMentions(importError(dir / "flat.obj"), {"flat.obj", "zero total area", "2 faces"});
}

}  // namespace
}  // namespace opal
