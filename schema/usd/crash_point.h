// A test hook for crash-consistency tests: when the environment variable OPAL_CRASH_AT
// names a point the process reaches, the process kills itself there with SIGKILL (no
// destructor, no atexit, no buffered output flushed: what a power cut or the out-of-memory
// killer leaves behind). Points are named "<step>:<moment>", e.g. "opal:written" (a
// sidecar's temporary file is complete, not yet renamed) or "bake:committed". Unset, or
// naming another point, it does nothing; it is meant for tests, never for users.
#pragma once

#include <string_view>

namespace opal {

inline constexpr const char* kCrashPointVariable = "OPAL_CRASH_AT";

// SIGKILLs the process when OPAL_CRASH_AT equals `point`.
void crashPoint(std::string_view point);

}  // namespace opal
