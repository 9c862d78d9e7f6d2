// A plugInfo.json manifest in USD's format (pxr/base/plug/info.cpp), read and validated:
//
//   # Lines whose first non-blank character is '#' are comments, as in USD.
//   {
//       "Includes": [ "*/", "more/plugInfo.json" ],
//       "Plugins": [ {
//           "Type": "library",                 "library" or "resource"
//           "Name": "opalDelegate",
//           "Root": "..",                      optional; relative to the manifest's directory
//           "LibraryPath": "opalDelegate.so",  required for "library"; relative to Root
//           "ResourcePath": "resources",       optional; relative to Root (default: Root)
//           "Info": { "Types": { "<TypeName>": { "bases": [ "HdRendererPlugin" ], ... } } }
//       } ]
//   }
//
// Includes are paths or wildcard patterns relative to the manifest's directory; one that
// ends in '/' names the plugInfo.json in that directory. '*' matches within one path
// component, '**' any number of directories (USD's rules).
//
// Reading is strict: any problem throws opal::Error naming the file, where in it, and
// what is wrong. A JSON syntax error is located as file:line:column (where the parser
// stopped: the last character of the offending token), anything else by its JSON
// location, e.g. "file: Plugins[0].Info.Types.T.bases: expected an array, found string". Unknown keys are not errors (USD reports and ignores them): they are
// listed in `warnings`.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

// One entry of a plugin's Info.Types: a type the plugin provides.
struct PluginType {
    std::string name;
    std::vector<std::string> bases;
    nlohmann::json metadata;  // the whole entry (bases, displayName, priority, ...)
    std::string location;     // "Plugins[0].Info.Types.<name>"
};

// One element of "Plugins".
struct PluginEntry {
    enum class Kind { Library, Resource };

    Kind kind = Kind::Library;
    std::string name;
    std::filesystem::path root;          // absolute
    std::filesystem::path libraryPath;   // absolute; empty when the plugin has no library
    std::filesystem::path resourcePath;  // absolute
    nlohmann::json info;                 // the whole "Info" object
    std::vector<PluginType> types;       // Info.Types, in key order
    std::string location;                // "Plugins[0]"
};

struct PluginManifest {
    std::filesystem::path path;         // the manifest file, absolute
    std::vector<PluginEntry> plugins;
    std::vector<std::string> includes;  // absolute paths or patterns, trailing '/' kept
    std::vector<std::string> warnings;  // unknown keys: "<file>: Plugins[0]: unknown key 'X'"
};

// Reads and validates the manifest at `file`; throws opal::Error.
PluginManifest readPluginManifest(const std::filesystem::path& file);

// The same from text already read; `file` names it in errors and anchors relative paths.
PluginManifest parsePluginManifest(std::string_view text, const std::filesystem::path& file);

// The manifest files an include names: the file itself when it has no wildcard (whether
// or not it exists), else every existing match, sorted.
std::vector<std::filesystem::path> expandIncludePattern(const std::string& pattern);

}  // namespace opal
