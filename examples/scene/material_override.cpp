#include "examples/scene/material_override.h"

#include "examples/scene/scene_material.h"
#include "schema/error.h"

namespace opal::scene {

void overrideMaterials(Scene& scene, std::string_view preset) {
    const std::optional<Material> material = findPreset(preset);
    if (!material)
        throw Error("material override '" + std::string(preset) + "': not a preset (" + presetNames() + ")");
    if (scene.materials.count(OverrideMaterialPath) || scene.meshes.count(OverrideMaterialPath) ||
        scene.lights.count(OverrideMaterialPath) || scene.cameras.count(OverrideMaterialPath))
        throw Error(scene.file.string() + ": the scene uses <" + OverrideMaterialPath +
                    ">, which the material override needs");
    hd::MaterialDesc desc;
    desc.subsurface = *material;
    scene.materials[OverrideMaterialPath] = SceneMaterial{desc, {}};
    for (auto& [path, mesh] : scene.meshes) mesh.desc.material = OverrideMaterialPath;
}

}  // namespace opal::scene
