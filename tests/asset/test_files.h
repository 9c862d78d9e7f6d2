// Test support: a fresh directory per test, whole-file byte I/O, and re-sealing the
// checksums of a container whose header or table a test edited on purpose (offsets from
// SIDECAR.md, not from the implementation).
#pragma once

#include "schema/asset/xxhash64.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include <unistd.h>

namespace opal::test {

// The bit patterns of `values`: equal when the floats are the same bit for bit (NaNs and
// signed zeros included), which EXPECT_EQ on floats does not say.
inline std::vector<std::uint32_t> bits(std::span<const float> values) {
    std::vector<std::uint32_t> out;
    out.reserve(values.size());
    for (const float v : values) out.push_back(std::bit_cast<std::uint32_t>(v));
    return out;
}

// The message of the opal::Error `f` throws; "NO ERROR" or "NOT AN opal::Error: ..."
// otherwise, which no expected message contains.
inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("NOT AN opal::Error: ") + e.what();
    }
    return "NO ERROR";
}

inline void expectContains(const std::string& text, std::initializer_list<std::string> parts) {
    for (const std::string& part : parts)
        EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}

class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                ("opal-asset-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" + info->name());
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path path_;
};

inline std::vector<std::byte> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::byte> bytes(chars.size());
    std::transform(chars.begin(), chars.end(), bytes.begin(), [](char c) { return std::byte(c); });
    return bytes;
}

// Replaces the file by a new one: truncating a file in place makes ext4 flush it on close
// (its replace-via-truncate heuristic), which turns a loop of rewrites into seconds.
inline void writeBytes(const std::filesystem::path& path, const std::vector<std::byte>& bytes) {
    std::filesystem::remove(path);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Overwrites one byte in place (no truncation, no new blocks: cheap even on ext4 with
// discard, where deleting or truncating files in a loop costs milliseconds each).
inline void patchByte(const std::filesystem::path& path, std::size_t at, std::byte value) {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(at));
    file.put(static_cast<char>(value));
}

inline std::uint64_t getU64(const std::vector<std::byte>& b, std::size_t at) {
    std::uint64_t v = 0;
    for (int i = 7; i >= 0; --i) v = (v << 8) | std::to_integer<std::uint64_t>(b[at + i]);
    return v;
}

inline void putU64(std::vector<std::byte>& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + i] = std::byte((v >> (8 * i)) & 0xFF);
}

inline void putU16(std::vector<std::byte>& b, std::size_t at, std::uint16_t v) {
    b[at] = std::byte(v & 0xFF);
    b[at + 1] = std::byte(v >> 8);
}

// SIDECAR.md: header checksum at 56 covers bytes 0..55; table checksum at 40 covers the
// table, which starts at the u64 at 24 and runs to the end of the file.
inline void resealHeader(std::vector<std::byte>& file) {
    putU64(file, 56, xxh64(std::span(file).first(56)));
}

inline void resealTable(std::vector<std::byte>& file) {
    std::uint64_t tableOffset = getU64(file, 24);
    putU64(file, 40, xxh64(std::span(file).subspan(tableOffset)));
    resealHeader(file);
}

}  // namespace opal::test
