// Whether Embree makes a device here, the check both renderer plugins' isSupported() make:
// yes on any processor these tests run on (Embree's defaults and the baseline SSE2
// kernels), and a clear error naming $OPAL_EMBREE_ISA for a value Embree does not know.
#include "raytrace/embree_device_config.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace opal {
namespace {

// Sets $OPAL_EMBREE_ISA (unset for nullopt) for one scope, then puts back what was there.
class IsaVariable {
public:
    explicit IsaVariable(const std::optional<std::string>& value) {
        if (const char* old = std::getenv(kEmbreeIsaVariable)) old_ = old;
        value ? setenv(kEmbreeIsaVariable, value->c_str(), 1) : unsetenv(kEmbreeIsaVariable);
    }
    ~IsaVariable() { old_ ? setenv(kEmbreeIsaVariable, old_->c_str(), 1) : unsetenv(kEmbreeIsaVariable); }
    IsaVariable(const IsaVariable&) = delete;
    IsaVariable& operator=(const IsaVariable&) = delete;

private:
    std::optional<std::string> old_;
};

TEST(EmbreeDevice, IsAvailableWithTheDefaultsAndTheBaselineKernels) {
    {
        const IsaVariable unset(std::nullopt);
        EXPECT_TRUE(embreeDeviceAvailable());
    }
    const IsaVariable baseline("sse2");
    EXPECT_TRUE(embreeDeviceAvailable());
}

TEST(EmbreeDevice, AnUnknownInstructionSetIsAnErrorNamingTheVariable) {
    const IsaVariable bad("avx3");
    try {
        embreeDeviceAvailable();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("OPAL_EMBREE_ISA = 'avx3'"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace opal
