#include "delegate/relight/recycled_buffer.h"

#include <utility>

namespace opal {

std::vector<float>& RecycledBuffer::next() {
    if (current_.use_count() > 1) {
        std::shared_ptr<std::vector<float>> free =
            spare_ && spare_.use_count() == 1 ? std::move(spare_) : std::make_shared<std::vector<float>>();
        spare_ = std::exchange(current_, std::move(free));
    }
    return *current_;
}

std::size_t RecycledBuffer::memoryBytes() const {
    return (current_->capacity() + (spare_ ? spare_->capacity() : 0)) * sizeof(float);
}

}  // namespace opal
