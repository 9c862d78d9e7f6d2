#include "schema/usd/crash_point.h"

#include <csignal>
#include <cstdlib>

#include <unistd.h>

namespace opal {

void crashPoint(std::string_view point) {
    const char* wanted = std::getenv(kCrashPointVariable);
    if (wanted == nullptr || point != wanted) return;
    ::kill(::getpid(), SIGKILL);
    ::_exit(137);  // not reached: SIGKILL cannot be caught
}

}  // namespace opal
