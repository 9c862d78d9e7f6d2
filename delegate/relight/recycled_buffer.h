// A buffer of floats that readers hold (shared, read-only) while its owner writes the
// next version: the relit vertex radiance and irradiance a render frame keeps while the
// next edit is relit. next() returns a vector no reader holds: the current one when no one
// else holds it, else the one before it once its readers let go, else a new one. A host
// that keeps only the last frame therefore costs no allocation per edit, and a held
// version never changes.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace opal {

class RecycledBuffer {
public:
    // The vector to write the next version into; it is current() from now on.
    std::vector<float>& next();

    const std::vector<float>& current() const { return *current_; }
    std::shared_ptr<const std::vector<float>> shared() const { return current_; }
    std::size_t memoryBytes() const;

private:
    std::shared_ptr<std::vector<float>> current_ = std::make_shared<std::vector<float>>();
    std::shared_ptr<std::vector<float>> spare_;
};

}  // namespace opal
