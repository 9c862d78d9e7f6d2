// Wall-clock milliseconds since construction (steady clock): the delegate's statistics
// and the benchmarks that read them time the same way.
#pragma once

#include <chrono>

namespace opal {

class Stopwatch {
public:
    double ms() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace opal
