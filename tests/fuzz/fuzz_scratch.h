// Opal's readers take file paths, so each fuzz input is written to a file in a private
// temporary folder: one per process, on /dev/shm when there is one (no disk traffic, and
// the container writer's fsync costs nothing there), removed when the process exits.
// Inputs never name files outside it (the scene target refuses such inputs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace opal::fuzz {

class Scratch {
public:
    Scratch() {
        std::filesystem::path base = std::filesystem::is_directory("/dev/shm") ? std::filesystem::path("/dev/shm")
                                                                              : std::filesystem::temp_directory_path();
        std::string pattern = (base / "opal-fuzz-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) {
            std::abort();  // no place for inputs: nothing can be fuzzed
        }
        dir_ = pattern;
    }
    ~Scratch() {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;

    const std::filesystem::path& dir() const { return dir_; }

    // Writes the bytes to dir()/name, replacing what was there.
    std::filesystem::path write(std::string_view name, const std::uint8_t* data, std::size_t size) const {
        std::filesystem::path path = dir_ / name;
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        return path;
    }

private:
    std::filesystem::path dir_;
};

// libFuzzer calls plain functions, so the folder lives as long as the process.
inline const Scratch& scratch() {
    static const Scratch folder;
    return folder;
}

}  // namespace opal::fuzz
