// A list of indices below a known limit (samples, input slots, cube-map texels), stored in
// 16 bits when the limit allows it (at most 65,536 values) and in 32 otherwise. The
// relighting kernels read one index per entry they stream, so the narrow form saves a
// quarter to a third of their bytes; they are written once for either width and take the
// list as a typed pointer (withData).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace opal {

class CompactIndices {
public:
    static constexpr std::size_t kNarrowLimit = std::size_t(1) << 16;

    CompactIndices() = default;
    // For indices below `limit`.
    explicit CompactIndices(std::size_t limit) : narrow_(limit <= kNarrowLimit) {}

    bool narrow() const { return narrow_; }
    std::size_t size() const { return narrow_ ? narrow16_.size() : wide_.size(); }
    void reserve(std::size_t count) { narrow_ ? narrow16_.reserve(count) : wide_.reserve(count); }
    // index: below the limit (the caller has checked it).
    void push_back(std::uint32_t index) {
        if (narrow_)
            narrow16_.push_back(std::uint16_t(index));
        else
            wide_.push_back(index);
    }
    void append(const std::vector<std::uint32_t>& indices) {
        if (narrow_)
            narrow16_.insert(narrow16_.end(), indices.begin(), indices.end());
        else
            wide_.insert(wide_.end(), indices.begin(), indices.end());
    }
    std::uint32_t operator[](std::size_t i) const { return narrow_ ? narrow16_[i] : wide_[i]; }

    // f(const std::uint16_t*) or f(const std::uint32_t*): the list as the kernels read it.
    template <typename F>
    decltype(auto) withData(F&& f) const {
        return narrow_ ? f(narrow16_.data()) : f(wide_.data());
    }

    std::size_t memoryBytes() const {
        return narrow16_.capacity() * sizeof(std::uint16_t) + wide_.capacity() * sizeof(std::uint32_t);
    }

private:
    bool narrow_ = true;
    std::vector<std::uint16_t> narrow16_;
    std::vector<std::uint32_t> wide_;
};

}  // namespace opal
