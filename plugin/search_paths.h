// Where hosts look for plugin manifests. The registry itself reads no environment: a host
// gathers its search paths once, at start-up, and passes them in:
//
//     PluginRegistry registry(hostSearchPaths(executablePath()));
//
// $OPAL_PLUGINPATH comes first, so users can override the shipped plugins; then the
// plugins next to the program (the build tree's, or the install prefix's), so an
// installed program needs no environment to find Opal's delegate.
//
// Each entry is a plugInfo.json file or a directory holding one.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

namespace opal {

// The entries of a colon-separated list, empty entries skipped.
std::vector<std::filesystem::path> splitSearchPath(std::string_view list);

// $OPAL_PLUGINPATH (or `variable`) split at colons; empty if unset.
std::vector<std::filesystem::path> searchPathsFromEnvironment(const char* variable = "OPAL_PLUGINPATH");

// The running program's file, from /proc/self/exe; throws opal::Error if unreadable.
std::filesystem::path executablePath();

// The plugin directories that exist for a program at `executable`: the build tree's
// <build>/lib/opal/plugins seen from <build>/bin, and the installed
// <prefix>/<libdir>/opal/plugins seen from <prefix>/<bindir>.
std::vector<std::filesystem::path> defaultSearchPaths(const std::filesystem::path& executable);

// What a host at `executable` searches: $OPAL_PLUGINPATH, then defaultSearchPaths.
std::vector<std::filesystem::path> hostSearchPaths(const std::filesystem::path& executable);

}  // namespace opal
