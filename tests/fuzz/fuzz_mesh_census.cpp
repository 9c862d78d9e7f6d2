// Bake's own mesh-file census (OBJ, PLY, STL face counts read without Assimp) on arbitrary
// bytes. The first byte picks the file's extension (0: .obj, 1: .ply, 2: .stl, modulo 3);
// the rest is the file. Anything but opal::Error escaping it is a finding.
#include "bake/mesh_file_census.h"
#include "schema/error.h"
#include "tests/fuzz/fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    static constexpr const char* kNames[] = {"mesh.obj", "mesh.ply", "mesh.stl"};
    std::filesystem::path path = opal::fuzz::scratch().write(kNames[data[0] % 3], data + 1, size - 1);
    try {
        opal::takeMeshFileCensus(path);
    } catch (const opal::Error&) {
    }
    return 0;
}
