// The fixture plugins tests/plugin/CMakeLists.txt builds, and whether one is loaded.
#pragma once

#include <dlfcn.h>

#include <filesystem>

namespace opal::test {

inline const std::filesystem::path FixtureDir = OPAL_TEST_PLUGIN_DIR;
inline const std::filesystem::path SupportedModule = FixtureDir / "opalTestRenderer" / "opalTestRenderer.so";

// Whether `library` is loaded in this process (dlopen with RTLD_NOLOAD loads nothing).
inline bool isLoaded(const std::filesystem::path& library) {
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_NOLOAD);
    if (handle) dlclose(handle);
    return handle != nullptr;
}

}  // namespace opal::test
