#include "plugin/search_paths.h"

#include "schema/error.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>
#include <utility>

// Both relative to the directory of the executable; set by plugin/CMakeLists.txt.
#ifndef OPAL_BUILD_PLUGIN_DIR
#error "OPAL_BUILD_PLUGIN_DIR must be defined by the build"
#endif
#ifndef OPAL_INSTALLED_PLUGIN_DIR
#error "OPAL_INSTALLED_PLUGIN_DIR must be defined by the build"
#endif

namespace opal {
namespace fs = std::filesystem;

std::vector<fs::path> splitSearchPath(std::string_view list) {
    std::vector<fs::path> paths;
    while (!list.empty()) {
        std::size_t colon = std::min(list.find(':'), list.size());
        if (colon > 0) paths.emplace_back(list.substr(0, colon));
        list.remove_prefix(std::min(colon + 1, list.size()));
    }
    return paths;
}

std::vector<fs::path> searchPathsFromEnvironment(const char* variable) {
    const char* value = std::getenv(variable);
    return value ? splitSearchPath(value) : std::vector<fs::path>{};
}

fs::path executablePath() {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("cannot find the running executable from /proc/self/exe: " + ec.message());
    return exe;
}

std::vector<fs::path> defaultSearchPaths(const fs::path& executable) {
    std::vector<fs::path> paths;
    const fs::path dir = executable.parent_path();
    for (const char* relative : {OPAL_BUILD_PLUGIN_DIR, OPAL_INSTALLED_PLUGIN_DIR}) {
        fs::path candidate = (dir / relative).lexically_normal();
        std::error_code ec;
        if (fs::is_directory(candidate, ec) && std::find(paths.begin(), paths.end(), candidate) == paths.end())
            paths.push_back(candidate);
    }
    return paths;
}

std::vector<fs::path> hostSearchPaths(const fs::path& executable) {
    std::vector<fs::path> paths = searchPathsFromEnvironment();
    for (fs::path& path : defaultSearchPaths(executable)) paths.push_back(std::move(path));
    return paths;
}

}  // namespace opal
