// Bake's USDA mesh import (every rendered Mesh prim merged, transforms applied) on arbitrary
// text. Anything but opal::Error escaping importUsdaMesh is a finding.
#include "bake/usda_mesh_import.h"
#include "schema/error.h"
#include "tests/fuzz/fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::filesystem::path path = opal::fuzz::scratch().write("mesh.usda", data, size);
    try {
        opal::importUsdaMesh(path);
    } catch (const opal::Error&) {
    }
    return 0;
}
