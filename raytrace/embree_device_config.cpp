#include "raytrace/embree_device_config.h"

#include "schema/error.h"

#include <embree3/rtcore.h>

#include <array>
#include <cstdlib>
#include <string_view>

namespace opal {

namespace {

// Embree 3.13's names for `max_isa` (its state.cpp, string_to_cpufeatures).
constexpr std::array<std::string_view, 5> kIsaNames = {"sse2", "sse4.2", "avx", "avx2", "avx512"};

}  // namespace

std::string embreeDeviceConfig() {
    const char* isa = std::getenv(kEmbreeIsaVariable);
    if (!isa || !*isa) return {};
    for (std::string_view name : kIsaNames)
        if (name == isa) return "max_isa=" + std::string(name);
    throw Error(std::string(kEmbreeIsaVariable) + " = '" + isa + "': not an instruction set Embree knows (sse2, "
                "sse4.2, avx, avx2 or avx512)");
}

bool embreeDeviceAvailable() {
    RTCDevice device = rtcNewDevice(embreeDeviceConfig().c_str());
    if (!device) return false;
    rtcReleaseDevice(device);
    return true;
}

}  // namespace opal
