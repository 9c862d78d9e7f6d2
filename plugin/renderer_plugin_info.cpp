#include "plugin/renderer_plugin_info.h"

#include "schema/error.h"

#include <algorithm>
#include <climits>

namespace opal {

namespace {

// The base type that makes a manifest type a renderer plugin (Hydra's name for it).
const char* const RendererPluginBase = "HdRendererPlugin";

bool isCIdentifier(std::string_view name) {
    auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    auto isIdentifierChar = [&](char c) { return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || isDigit(c); };
    return !name.empty() && !isDigit(name.front()) && std::all_of(name.begin(), name.end(), isIdentifierChar);
}

[[noreturn]] void failAt(const PluginManifest& manifest, const std::string& where, const std::string& problem) {
    throw Error(manifest.path.string() + ": " + where + ": " + problem);
}

std::string displayNameOf(const PluginManifest& manifest, const PluginType& type) {
    auto it = type.metadata.find("displayName");
    if (it == type.metadata.end()) failAt(manifest, type.location, "renderer plugin type has no 'displayName'");
    if (!it->is_string() || it->get<std::string>().empty())
        failAt(manifest, type.location + ".displayName", "expected a non-empty string, found " + it->dump());
    return it->get<std::string>();
}

int priorityOf(const PluginManifest& manifest, const PluginType& type) {
    auto it = type.metadata.find("priority");
    if (it == type.metadata.end()) failAt(manifest, type.location, "renderer plugin type has no 'priority'");
    if (!it->is_number_integer()) failAt(manifest, type.location + ".priority", std::string("expected an integer, found ") + it->type_name());
    bool inRange = it->is_number_unsigned() ? it->get<unsigned long long>() <= INT_MAX
                                            : it->get<long long>() >= INT_MIN && it->get<long long>() <= INT_MAX;
    if (!inRange) failAt(manifest, type.location + ".priority", "out of range for an int: " + it->dump());
    return it->get<int>();
}

std::string factoryOf(const PluginManifest& manifest, const PluginType& type) {
    auto it = type.metadata.find("factory");
    if (it == type.metadata.end()) {
        if (!isCIdentifier(type.name))
            failAt(manifest, type.location, "type name is not a C identifier, so it needs a \"factory\" symbol name");
        return type.name + "_create";
    }
    if (!it->is_string() || !isCIdentifier(it->get<std::string>()))
        failAt(manifest, type.location + ".factory", "expected a C function name, found " + it->dump());
    return it->get<std::string>();
}

}  // namespace

std::string describeRendererPlugin(const RendererPluginInfo& info) {
    return info.displayName + " (" + info.typeName + ", priority " + std::to_string(info.priority) + ")";
}

bool isRendererPluginType(const PluginType& type) {
    return std::find(type.bases.begin(), type.bases.end(), RendererPluginBase) != type.bases.end();
}

RendererPluginInfo readRendererPluginInfo(const PluginManifest& manifest, const PluginEntry& plugin,
                                          const PluginType& type) {
    if (plugin.kind != PluginEntry::Kind::Library || plugin.libraryPath.empty())
        failAt(manifest, type.location, "a renderer plugin type must come from a \"library\" plugin with a LibraryPath");
    RendererPluginInfo info;
    info.typeName = type.name;
    info.displayName = displayNameOf(manifest, type);
    info.priority = priorityOf(manifest, type);
    info.pluginName = plugin.name;
    info.libraryPath = plugin.libraryPath;
    info.manifestPath = manifest.path;
    info.factorySymbol = factoryOf(manifest, type);
    return info;
}

}  // namespace opal
