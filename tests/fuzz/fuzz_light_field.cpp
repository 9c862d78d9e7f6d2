// The light sidecar reader (schema/asset/LIGHTFIELD.md) on arbitrary bytes: the container
// and every check of the field behind it. Anything but opal::Error escaping
// readShadowFieldFile is a finding; so are an allocation above -malloc_limit_mb and a leak.
#include "schema/asset/shadow_field_file.h"
#include "schema/error.h"
#include "tests/fuzz/fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::filesystem::path path = opal::fuzz::scratch().write("fuzz.opal", data, size);
    try {
        opal::readShadowFieldFile(path);
    } catch (const opal::Error&) {
    }
    return 0;
}
