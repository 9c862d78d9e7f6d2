// The sidecar reader on arbitrary bytes: header, chunk table, checksums and everything
// behind them. Anything but opal::Error escaping readSidecar is a finding; so are an
// allocation above -malloc_limit_mb and a leak.
#include "schema/asset/sidecar.h"
#include "schema/error.h"
#include "tests/fuzz/fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::filesystem::path path = opal::fuzz::scratch().write("fuzz.opal", data, size);
    try {
        opal::TranslucentAsset asset;
        opal::readSidecar(path, asset);
    } catch (const opal::Error&) {
    }
    return 0;
}
