#include "bake/mesh_file_census.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>

namespace opal {
namespace {

std::string lowercaseExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// True when `line`, after leading blanks, starts with the keyword followed by a blank.
bool startsWithKeyword(const std::string& line, std::string_view keyword) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line.compare(i, keyword.size(), keyword) != 0) return false;
    std::size_t after = i + keyword.size();
    return after < line.size() && (line[after] == ' ' || line[after] == '\t');
}

std::uint64_t countKeywordLines(const std::filesystem::path& path, std::string_view keyword) {
    std::ifstream in(path);
    std::uint64_t count = 0;
    for (std::string line; std::getline(in, line);) {
        if (startsWithKeyword(line, keyword)) ++count;
    }
    return count;
}

std::optional<MeshFileCensus> censusObj(const std::filesystem::path& path) {
    std::uint64_t faces = countKeywordLines(path, "f");
    return MeshFileCensus{faces, 0, std::to_string(faces) + " 'f' lines", ""};
}

// ASCII PLY has one line per element (vertex, face, ...) after the header.
std::optional<MeshFileCensus> censusPly(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::optional<MeshFileCensus> census;
    std::uint64_t declaredElements = 0;
    bool ascii = false, headerEnded = false;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line == "end_header") {
            headerEnded = true;
            break;
        }
        std::istringstream words(line);
        std::string keyword, name;
        std::uint64_t count = 0;
        words >> keyword >> name;
        if (keyword == "format") ascii = name == "ascii";
        if (keyword != "element" || !(words >> count)) continue;
        // Saturating: a declared count near 2^64 must not wrap into a small one.
        declaredElements = count > UINT64_MAX - declaredElements ? UINT64_MAX : declaredElements + count;
        if (name != "face" && name != "tristrips") continue;
        if (!census) census = MeshFileCensus{};
        const std::string declared = "'element " + name + " " + std::to_string(count) + "'";
        census->evidence += (census->evidence.empty() ? "the header's " : " and ") + declared;
        (name == "face" ? census->faces : census->triangleStrips) = count;
    }
    if (!census || !headerEnded || !ascii) return census;
    std::uint64_t dataLines = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") != std::string::npos) ++dataLines;
    }
    if (dataLines < declaredElements) {
        census->inconsistency = "the header declares " + std::to_string(declaredElements) +
                                " elements but only " + std::to_string(dataLines) + " data lines follow";
    }
    return census;
}

// Binary STL: 80-byte header, uint32 triangle count, 50 bytes per triangle. A file is
// binary when its size matches that layout (even if its header starts with "solid", as
// some exporters write) or when it does not start with "solid" at all.
std::optional<MeshFileCensus> censusStl(const std::filesystem::path& path) {
    std::uintmax_t size = std::filesystem::file_size(path);
    if (size >= 84) {
        std::ifstream in(path, std::ios::binary);
        unsigned char header[84];
        in.read(reinterpret_cast<char*>(header), sizeof header);
        std::uint32_t triangles = std::uint32_t(header[80]) | std::uint32_t(header[81]) << 8 |
                                  std::uint32_t(header[82]) << 16 | std::uint32_t(header[83]) << 24;
        bool saysSolid = std::memcmp(header, "solid", 5) == 0;
        std::uintmax_t expectedSize = 84 + 50 * std::uintmax_t(triangles);
        if (in && (size == expectedSize || !saysSolid)) {
            MeshFileCensus census{triangles, 0, "the binary header's count of " + std::to_string(triangles) + " triangles", ""};
            if (size != expectedSize) {
                census.inconsistency = "the binary header declares " + std::to_string(triangles) + " triangles (" +
                                       std::to_string(expectedSize) + " bytes) but the file has " +
                                       std::to_string(size) + " bytes";
            }
            return census;
        }
    }
    std::uint64_t facets = countKeywordLines(path, "facet");
    return MeshFileCensus{facets, 0, std::to_string(facets) + " 'facet' lines", ""};
}

}  // namespace

std::optional<MeshFileCensus> takeMeshFileCensus(const std::filesystem::path& path) {
    std::string ext = lowercaseExtension(path);
    if (ext == ".obj") return censusObj(path);
    if (ext == ".ply") return censusPly(path);
    if (ext == ".stl") return censusStl(path);
    return std::nullopt;
}

}  // namespace opal
