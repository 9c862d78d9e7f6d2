// The material a mesh renders with, as every delegate resolves its binding (MeshDesc's
// material path): the bound material prim's description, or with no binding the asset's
// default subsurface material under MaterialDesc's default specular layer.
#pragma once

#include "delegate/hd/scene_delegate.h"

namespace opal::hd {

// `bound`: the description of the material prim at `binding` (the delegate finds it in its
// render index), null when there is none. With an empty binding, `asset`'s default
// material and MaterialDesc's specular defaults. Throws opal::Error "its material 'PATH' is
// not a material prim of the render index" for a binding with `bound` null.
MaterialDesc meshMaterial(const SdfPath& binding, const TranslucentAsset& asset, const MaterialDesc* bound);

}  // namespace opal::hd
