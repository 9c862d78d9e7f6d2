// opal-bake computes on glibc's baseline (SSE2) libm on every x86-64 processor. glibc picks
// the variants of exp, log, pow, sin, cos, sincos, atan2, expm1 and log1p at run time (FMA
// with AVX2, FMA4 or AVX where the processor has them), and they round differently from the
// SSE2 ones for roughly one input in a thousand (measured over 2 million inputs each on
// glibc 2.36); the profile basis, the procedural meshes and the sample elimination carry
// that last bit into a bake's bytes, so nodes of a farm with different processors wrote
// different assets. The float functions (expf, logf, powf, sinf, cosf, acosf, asinf) agreed
// everywhere. glibc lets a process turn those variants off only before it starts
// (GLIBC_TUNABLES glibc.cpu.hwcaps), so opal-bake restarts itself once when they are on.
#pragma once

#include <string>

namespace opal {

// The features whose libm variants opal-bake turns off, in glibc.cpu.hwcaps's syntax.
inline constexpr const char* kBaselineMathHwcaps = "-AVX,-AVX2,-FMA,-FMA4";

// GLIBC_TUNABLES `current` (may be empty) with kBaselineMathHwcaps added: appended to its
// glibc.cpu.hwcaps entry when it has one (the last entry of a name is the one glibc keeps),
// else as a new entry.
std::string withBaselineMath(const std::string& current);

// Returns when the process already uses the baseline variants (or is not x86-64 glibc);
// else sets GLIBC_TUNABLES and replaces the process with itself (same pid, arguments and
// environment otherwise). Throws opal::Error when glibc ignored the setting of a restart
// (a set-user-id program, say): the bake would not be reproducible.
void runOnBaselineMath(char** argv);

}  // namespace opal
