// Prim paths the viewer makes (a light added or renamed): absolute, each element a USD
// identifier ([A-Za-z_][A-Za-z0-9_]*), and not taken by a prim of the scene.
#pragma once

#include "examples/scene/scene.h"

#include <string>
#include <string_view>

namespace opal::view {

bool isIdentifier(std::string_view name);
// Throws opal::Error saying why `path` cannot be a new prim of `scene`.
void requireNewPrimPath(const scene::Scene& scene, const hd::SdfPath& path);
// The last element of `path` (the prim's name).
std::string primName(const hd::SdfPath& path);
// `path` with its last element replaced by `name`.
hd::SdfPath siblingPath(const hd::SdfPath& path, std::string_view name);

}  // namespace opal::view
