// The USDA reader on arbitrary text. Anything but opal::Error escaping it is a finding, and
// so is a layer that does not survive the writer: what the reader accepts, writeUsda
// either refuses with opal::Error or writes as text that reads back to the same layer.
#include "schema/error.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    opal::usda::Layer layer;
    try {
        layer = opal::usda::readUsda(text, "fuzz.usda");
    } catch (const opal::Error&) {
        return 0;
    }
    std::string written;
    try {
        written = opal::usda::writeUsda(layer);
    } catch (const opal::Error&) {
        return 0;
    }
    try {
        if (opal::usda::readUsda(written, "written.usda") == layer) {
            return 0;
        }
        std::fprintf(stderr, "the written layer reads back different:\n%s\n", written.c_str());
    } catch (const opal::Error& e) {
        std::fprintf(stderr, "the written layer does not read back: %s\n%s\n", e.what(), written.c_str());
    }
    std::abort();
}
