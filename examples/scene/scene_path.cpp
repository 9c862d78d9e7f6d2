#include "examples/scene/scene_path.h"

#include "schema/error.h"

#include <vector>

namespace opal::scene {
namespace {

std::vector<std::string_view> splitElements(std::string_view path) {
    std::vector<std::string_view> elements;
    while (!path.empty()) {
        const std::size_t slash = path.find('/');
        const std::string_view element = path.substr(0, slash);
        if (!element.empty()) elements.push_back(element);
        if (slash == std::string_view::npos) break;
        path.remove_prefix(slash + 1);
    }
    return elements;
}

}  // namespace

hd::SdfPath childPath(const hd::SdfPath& parent, std::string_view name) {
    return (parent == "/" ? parent : parent + "/") + std::string(name);
}

hd::SdfPath resolveTargetPath(const hd::SdfPath& anchor, std::string_view target) {
    std::vector<std::string_view> elements = target.starts_with('/') ? std::vector<std::string_view>{}
                                                                       : splitElements(anchor);
    for (std::string_view element : splitElements(target)) {
        if (element == ".") continue;
        if (element == "..") {
            if (elements.empty())
                throw Error("<" + std::string(target) + "> climbs above the root from <" + anchor + ">");
            elements.pop_back();
            continue;
        }
        if (element.find('.') != std::string_view::npos)
            throw Error("<" + std::string(target) + "> is a property path; a prim path is expected");
        elements.push_back(element);
    }
    hd::SdfPath path = "/";
    for (std::string_view element : elements) path = childPath(path, element);
    return path;
}

}  // namespace opal::scene
