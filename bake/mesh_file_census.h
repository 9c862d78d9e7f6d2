// What a mesh file says about its own size, read without a full parser. Importers
// sometimes return a nearly empty mesh without reporting an error (a reader that stops at
// the first construct it does not understand); comparing against the census catches it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace opal {

struct MeshFileCensus {
    std::uint64_t faces = 0;  // faces (polygons, or triangles for STL) the file holds
    // PLY only: records of a 'tristrips' element (each a strip list with -1 restarts),
    // which hold faces that `faces` does not count.
    std::uint64_t triangleStrips = 0;
    std::string evidence;     // how the count was obtained, for the error message
    // Set when the file contradicts itself, e.g. a header that declares more data than
    // follows it (a truncated file; some readers then invent the missing faces).
    std::string inconsistency;
};

// Counts faces in OBJ ('f' lines), PLY (the header's "element face" and "element
// tristrips"; for ASCII PLY also checks that a data line follows for every declared
// element), and STL (binary header
// count, checked against the file size; or ASCII "facet" lines). Other formats have no
// cheap count: nullopt.
std::optional<MeshFileCensus> takeMeshFileCensus(const std::filesystem::path& path);

}  // namespace opal
