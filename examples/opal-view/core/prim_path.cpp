#include "examples/opal-view/core/prim_path.h"

#include "schema/error.h"

namespace opal::view {
namespace {

bool isPrimPath(const hd::SdfPath& path) {
    if (path.size() < 2 || path.front() != '/') return false;
    for (std::size_t start = 1; start <= path.size();) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        if (!isIdentifier(std::string_view(path).substr(start, end - start))) return false;
        start = end + 1;
    }
    return true;
}

template <class Prims>
bool holds(const Prims& prims, const hd::SdfPath& path) {
    return prims.count(path) > 0;
}

}  // namespace

bool isIdentifier(std::string_view name) {
    if (name.empty()) return false;
    const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (!letter(name.front())) return false;
    for (const char c : name)
        if (!letter(c) && !(c >= '0' && c <= '9')) return false;
    return true;
}

void requireNewPrimPath(const scene::Scene& scene, const hd::SdfPath& path) {
    if (!isPrimPath(path))
        throw Error("<" + path + "> is not a prim path (/Name/Name..., each name a letter or _ followed by letters, "
                    "digits or _)");
    if (holds(scene.meshes, path) || holds(scene.materials, path) || holds(scene.lights, path) ||
        holds(scene.cameras, path) || (scene.renderSettings && scene.renderSettings->path == path))
        throw Error("the scene already has a prim at <" + path + ">");
}

std::string primName(const hd::SdfPath& path) { return path.substr(path.find_last_of('/') + 1); }

hd::SdfPath siblingPath(const hd::SdfPath& path, std::string_view name) {
    return path.substr(0, path.find_last_of('/') + 1) + std::string(name);
}

}  // namespace opal::view
