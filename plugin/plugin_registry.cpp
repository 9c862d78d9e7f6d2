#include "plugin/plugin_registry.h"

#include "schema/error.h"

#include <algorithm>

namespace opal {
namespace fs = std::filesystem;

namespace {

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

}  // namespace

PluginRegistry::PluginRegistry(std::vector<fs::path> searchPaths) : searchPaths_(std::move(searchPaths)) {
    for (const fs::path& path : searchPaths_) readSearchPath(path);
    std::stable_sort(renderers_.begin(), renderers_.end(), [](const RendererPluginInfo& a, const RendererPluginInfo& b) {
        return a.priority != b.priority ? a.priority < b.priority : a.typeName < b.typeName;
    });
}

void PluginRegistry::readSearchPath(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        problems_.push_back(path.string() + ": plugin search path does not exist");
        return;
    }
    readManifest(fs::is_directory(path, ec) ? path / "plugInfo.json" : path);
}

void PluginRegistry::readManifest(const fs::path& file) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(fs::absolute(file), ec);
    if (!visited_.insert(ec ? file : canonical).second) return;  // read already (or an Includes cycle)
    PluginManifest manifest;
    try {
        manifest = readPluginManifest(file);
    } catch (const Error& e) {
        problems_.push_back(e.what());
        return;
    }
    manifests_.push_back(manifest.path);
    problems_.insert(problems_.end(), manifest.warnings.begin(), manifest.warnings.end());
    for (const PluginEntry& plugin : manifest.plugins) addRendererTypes(manifest, plugin);
    for (const std::string& include : manifest.includes)
        for (const fs::path& included : expandIncludePattern(include)) readManifest(included);
}

void PluginRegistry::addRendererTypes(const PluginManifest& manifest, const PluginEntry& plugin) {
    for (const PluginType& type : plugin.types) {
        if (!isRendererPluginType(type)) continue;
        try {
            addRenderer(readRendererPluginInfo(manifest, plugin, type), manifest.path.string() + ": " + type.location);
        } catch (const Error& e) {
            problems_.push_back(e.what());
        }
    }
}

void PluginRegistry::addRenderer(RendererPluginInfo info, const std::string& location) {
    if (const RendererPluginInfo* first = findRendererPlugin(info.typeName)) {
        problems_.push_back(location + ": renderer plugin type '" + info.typeName + "' is declared already by " +
                            first->manifestPath.string() + "; this declaration is ignored");
        return;
    }
    renderers_.push_back(std::move(info));
}

const RendererPluginInfo* PluginRegistry::findRendererPlugin(std::string_view typeName) const {
    auto it = std::find_if(renderers_.begin(), renderers_.end(), [&](const RendererPluginInfo& r) { return r.typeName == typeName; });
    return it == renderers_.end() ? nullptr : &*it;
}

const RendererPluginInfo& PluginRegistry::requireRendererPlugin(std::string_view typeName) const {
    const RendererPluginInfo* info = findRendererPlugin(typeName);
    if (!info) throw Error(noPluginMessage(typeName));
    return *info;
}

RendererPluginHandle PluginRegistry::createRendererPlugin(std::string_view typeName) const {
    return create(requireRendererPlugin(typeName));
}

RendererPluginHandle PluginRegistry::create(const RendererPluginInfo& info) const {
    const std::string context = "renderer plugin '" + info.typeName + "' (" + info.manifestPath.string() + "): ";
    std::shared_ptr<SharedLibrary> library;
    RendererPluginFactory* factory = nullptr;
    try {
        library = SharedLibrary::open(info.libraryPath);
        factory = reinterpret_cast<RendererPluginFactory*>(library->symbol(info.factorySymbol));
    } catch (const Error& e) {
        throw Error(context + e.what());
    }
    std::unique_ptr<RendererPlugin> plugin;
    try {
        plugin.reset(factory());
    } catch (const std::exception& e) {
        throw Error(context + "factory '" + info.factorySymbol + "' failed: " + e.what());
    }
    if (!plugin) throw Error(context + "factory '" + info.factorySymbol + "' in " + info.libraryPath.string() + " returned null");
    return RendererPluginHandle(info, std::move(plugin), std::move(library));
}

RendererPluginHandle PluginRegistry::defaultRendererPlugin() const {
    std::vector<std::string> passedOver;
    for (const RendererPluginInfo& info : renderers_) {
        try {
            RendererPluginHandle handle = create(info);
            if (handle->isSupported()) return handle;
            passedOver.push_back("renderer plugin '" + info.typeName + "': not supported here");
        } catch (const std::exception& e) {
            passedOver.push_back(e.what());
        }
    }
    if (passedOver.empty()) throw Error(noPluginMessage(""));
    throw Error("no supported renderer plugin: " + joined(passedOver, "; "));
}

std::string PluginRegistry::noPluginMessage(std::string_view typeName) const {
    std::vector<std::string> available, paths;
    for (const RendererPluginInfo& info : renderers_) available.push_back(describeRendererPlugin(info));
    for (const fs::path& path : searchPaths_) paths.push_back(path.string());
    std::string message = typeName.empty() ? "no renderer plugin found" : "no renderer plugin '" + std::string(typeName) + "'";
    message += " (available: " + (available.empty() ? std::string("none") : joined(available, ", ")) +
               "; search paths: " + (paths.empty() ? std::string("none") : joined(paths, ":")) + ")";
    if (!problems_.empty()) message += "; problems while reading manifests: " + joined(problems_, "; ");
    return message;
}

}  // namespace opal
