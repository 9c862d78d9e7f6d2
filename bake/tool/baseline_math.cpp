#include "bake/tool/baseline_math.h"

#include "schema/error.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

#if defined(__x86_64__) && defined(__GLIBC__)
#include <sys/platform/x86.h>
#define OPAL_GLIBC_X86_64 1
#else
#define OPAL_GLIBC_X86_64 0
#endif

namespace opal {

namespace {

constexpr const char* kHwcaps = "glibc.cpu.hwcaps=";

bool variantsActive() {
#if OPAL_GLIBC_X86_64
    return CPU_FEATURE_ACTIVE(AVX) || CPU_FEATURE_ACTIVE(AVX2) || CPU_FEATURE_ACTIVE(FMA) || CPU_FEATURE_ACTIVE(FMA4);
#else
    return false;
#endif
}

}  // namespace

std::string withBaselineMath(const std::string& current) {
    std::istringstream entries(current);
    std::string entry, merged;
    bool added = false;
    while (std::getline(entries, entry, ':')) {
        if (entry.rfind(kHwcaps, 0) == 0) {
            entry += (entry.size() > std::strlen(kHwcaps) ? "," : "") + std::string(kBaselineMathHwcaps);
            added = true;
        }
        merged += (merged.empty() ? "" : ":") + entry;
    }
    if (!added) merged += (merged.empty() ? "" : ":") + std::string(kHwcaps) + kBaselineMathHwcaps;
    return merged;
}

void runOnBaselineMath(char** argv) {
    if (!variantsActive()) return;
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    const std::string current = tunables ? tunables : "";
    if (current.find(kBaselineMathHwcaps) != std::string::npos)
        throw Error("glibc ignored GLIBC_TUNABLES=" + current +
                    ": its FMA/AVX variants of exp, log, sin and cos stay on, and the bake's bytes would depend on "
                    "this processor");
    const std::string wanted = withBaselineMath(current);
    setenv("GLIBC_TUNABLES", wanted.c_str(), 1);
    execv("/proc/self/exe", argv);
    throw Error(std::string("cannot restart opal-bake on glibc's baseline math (/proc/self/exe): ") +
                std::strerror(errno));
}

}  // namespace opal
