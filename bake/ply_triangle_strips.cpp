#include "bake/ply_triangle_strips.h"

#include "bake/ply_values.h"
#include "schema/error.h"

#include <limits>
#include <optional>
#include <string>

namespace opal {
namespace {

constexpr std::string_view kStripElement = "tristrips";
constexpr std::int32_t kRestart = -1;

// Where a value is read, for messages: "element 'tristrips' 0, property 'vertex_indices'".
std::string place(const PlyElement& element, std::uint64_t index, const PlyProperty& property) {
    return "element '" + element.name + "' " + std::to_string(index) + ", property '" + property.name + "'";
}

std::optional<std::size_t> findProperty(const PlyElement& element, std::string_view name) {
    for (std::size_t p = 0; p < element.properties.size(); ++p)
        if (element.properties[p].name == name) return p;
    return std::nullopt;
}

// The list that holds a face's or strip's corners.
std::optional<std::size_t> findIndexList(const PlyElement& element) {
    for (std::string_view name : {"vertex_indices", "vertex_index"}) {
        const std::optional<std::size_t> p = findProperty(element, name);
        if (p && element.properties[*p].isList) return p;
    }
    return std::nullopt;
}

class StripMeshReader {
public:
    StripMeshReader(const std::filesystem::path& path, std::string_view bytes, const PlyHeader& header)
        : file_(path.string()), header_(header), values_(bytes.substr(header.dataOffset), header.format) {
        out_.mesh.source = file_;
    }

    PlyStripMesh read() {
        const PlyElement* vertex = header_.find("vertex");
        if (!vertex) fail("the header declares no 'vertex' element");
        if (vertex->count > std::uint64_t(std::numeric_limits<std::int32_t>::max()))
            fail("'element vertex " + std::to_string(vertex->count) + "' is more vertices than Opal indexes");
        for (const PlyElement& element : header_.elements) {
            if (&element == vertex) readVertices(element);
            else if (element.name == kStripElement) readLists(element, true);
            else if (element.name == "face") readLists(element, false);
            else skipElement(element);
        }
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw Error(file_ + ": " + problem); }

    // The declared count must fit in the bytes left: nothing is sized from a count the
    // file cannot hold.
    void requireRoom(const PlyElement& element) {
        PlyScalar smallest = PlyScalar::Float64;
        for (const PlyProperty& p : element.properties) {
            const PlyScalar t = p.isList ? p.countType : p.type;
            if (plyScalarSize(t) < plyScalarSize(smallest)) smallest = t;
        }
        const std::uint64_t perRecord = element.properties.size();
        const bool overflows = perRecord > 0 && element.count > std::numeric_limits<std::uint64_t>::max() / perRecord;
        if (perRecord > 0 && (overflows || !values_.couldHold(element.count * perRecord, smallest)))
            fail("'element " + element.name + " " + std::to_string(element.count) +
                 "' declares more data than the file holds (truncated?)");
    }

    // One record's properties; `use` receives each value (a list's items as integers).
    template <typename Use>
    void readRecord(const PlyElement& element, std::uint64_t index, Use&& use) {
        for (const PlyProperty& p : element.properties) {
            try {
                if (!p.isList) {
                    use(p, values_.real(p.type));
                    continue;
                }
                const std::int64_t length = values_.integer(p.countType);
                if (length < 0 || !values_.couldHold(std::uint64_t(length), p.type))
                    throw Error("a list length of " + std::to_string(length) + " that the file cannot hold");
                use.list(p, std::uint64_t(length));
            } catch (const Error& e) {
                fail(place(element, index, p) + ": " + e.what());
            }
        }
    }

    void readVertices(const PlyElement& element) {
        const std::optional<std::size_t> axes[3] = {findProperty(element, "x"), findProperty(element, "y"),
                                                    findProperty(element, "z")};
        for (const auto& axis : axes)
            if (!axis || element.properties[*axis].isList)
                fail("element 'vertex' has no scalar x, y and z properties");
        requireRoom(element);
        out_.mesh.positions.reserve(element.count);
        struct Use {
            StripMeshReader& reader;
            Imath::V3f point;
            void operator()(const PlyProperty& p, double value) {
                if (p.name == "x") point.x = float(value);
                else if (p.name == "y") point.y = float(value);
                else if (p.name == "z") point.z = float(value);
            }
            void list(const PlyProperty& p, std::uint64_t length) { reader.skipList(p, length); }
        };
        for (std::uint64_t v = 0; v < element.count; ++v) {
            Use use{*this, Imath::V3f(0.0f)};
            readRecord(element, v, use);
            out_.mesh.positions.push_back(use.point);
        }
    }

    void skipList(const PlyProperty& p, std::uint64_t length) {
        for (std::uint64_t i = 0; i < length; ++i) values_.real(p.type);
    }

    // A vertex index: -1 (a restart, strips only) or a vertex of the file.
    std::int32_t vertexIndex(const PlyProperty& p, std::uint64_t item, bool strip) {
        const std::int64_t index = values_.integer(p.type);
        const std::int64_t vertices = std::int64_t(out_.mesh.positions.size());
        if ((strip && index == kRestart) || (index >= 0 && index < vertices)) return std::int32_t(index);
        throw Error("item " + std::to_string(item) + " is " + std::to_string(index) + ", which is " +
                    (strip ? "neither -1 (a restart) nor " : "not ") + "a vertex (the file has " +
                    std::to_string(vertices) + ")");
    }

    void readLists(const PlyElement& element, bool strips) {
        const std::optional<std::size_t> list = findIndexList(element);
        if (!list) fail("element '" + element.name + "' has no 'vertex_indices' list");
        if (!plyScalarIsInteger(element.properties[*list].type))
            fail("element '" + element.name + "' stores its vertex indices as floats");
        requireRoom(element);
        struct Use {
            StripMeshReader& reader;
            const PlyProperty& indices;
            bool strips;
            std::vector<std::int32_t> corners;
            void operator()(const PlyProperty&, double) {}
            void list(const PlyProperty& p, std::uint64_t length) {
                if (&p != &indices) return reader.skipList(p, length);
                for (std::uint64_t i = 0; i < length; ++i) corners.push_back(reader.vertexIndex(p, i, strips));
            }
        };
        for (std::uint64_t r = 0; r < element.count; ++r) {
            Use use{*this, element.properties[*list], strips, {}};
            readRecord(element, r, use);
            strips ? addStrip(use.corners) : addPolygon(use.corners);
        }
    }

    void addStrip(const std::vector<std::int32_t>& indices) {
        StripTriangles triangles;
        decodeTriangleStrip(indices, triangles);
        out_.degenerate += triangles.degenerate;
        out_.stripTriangles += triangles.corners.size() / 3;
        ControlMesh& m = out_.mesh;
        m.faceVertexIndices.insert(m.faceVertexIndices.end(), triangles.corners.begin(), triangles.corners.end());
        m.faceVertexCounts.insert(m.faceVertexCounts.end(), triangles.corners.size() / 3, 3);
    }

    // Polygons as authored (fewer than 3 corners: refused later by mesh validation).
    void addPolygon(const std::vector<std::int32_t>& corners) {
        ControlMesh& m = out_.mesh;
        m.faceVertexCounts.push_back(std::int32_t(corners.size()));
        m.faceVertexIndices.insert(m.faceVertexIndices.end(), corners.begin(), corners.end());
    }

    void skipElement(const PlyElement& element) {
        if (element.properties.empty()) return;  // records of nothing: no bytes to skip
        requireRoom(element);
        struct Use {
            StripMeshReader& reader;
            void operator()(const PlyProperty&, double) {}
            void list(const PlyProperty& p, std::uint64_t length) { reader.skipList(p, length); }
        };
        for (std::uint64_t r = 0; r < element.count; ++r) {
            Use use{*this};
            readRecord(element, r, use);
        }
    }

    std::string file_;
    const PlyHeader& header_;
    PlyValueReader values_;
    PlyStripMesh out_;
};

}  // namespace

void decodeTriangleStrip(std::span<const std::int32_t> indices, StripTriangles& out) {
    std::size_t run = 0;  // vertices since the strip (re)started
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] == kRestart) {
            run = 0;
            continue;
        }
        if (++run < 3) continue;
        const std::int32_t a = indices[i - 2], b = indices[i - 1], c = indices[i];
        if (a == b || b == c || a == c) {
            ++out.degenerate;
            continue;
        }
        const bool odd = (run - 3) % 2 == 1;  // triangle k = run - 3 of this run
        out.corners.insert(out.corners.end(), {odd ? b : a, odd ? a : b, c});
    }
}

bool declaresTriangleStrips(const PlyHeader& header) { return header.find(kStripElement) != nullptr; }

PlyStripMesh readPlyTriangleStrips(const std::filesystem::path& path, std::string_view bytes,
                                   const PlyHeader& header) {
    return StripMeshReader(path, bytes, header).read();
}

}  // namespace opal
