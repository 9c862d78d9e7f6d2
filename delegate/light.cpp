#include "delegate/light.h"

#include "schema/error.h"

#include <cmath>

namespace opal {

namespace {

hd::LightKind kindOf(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::SphereLight) return hd::LightKind::Sphere;
    if (type == hd::PrimType::DistantLight) return hd::LightKind::Distant;
    if (type == hd::PrimType::DomeLight) return hd::LightKind::Dome;
    if (type == hd::PrimType::ShadowFieldLight) return hd::LightKind::ShadowField;
    throw Error("light '" + id + "': Opal's lights are sphereLight, distantLight, domeLight and " +
                hd::PrimType::ShadowFieldLight + ", not '" + type + "'");
}

}  // namespace

const char* lightKindName(hd::LightKind kind) {
    switch (kind) {
        case hd::LightKind::Sphere: return "sphere";
        case hd::LightKind::Distant: return "distant";
        case hd::LightKind::Dome: return "dome";
        case hd::LightKind::ShadowField: return "shadow field";
    }
    return "unknown";
}

OpalLight::OpalLight(const hd::SdfPath& id, const hd::Token& type, DomeTextureCache& textures,
                     ShadowFieldCache& fields, PrimVersions& versions)
    : hd::Sprim(id), kind_(kindOf(type, id)), textures_(textures), fields_(fields), versions_(versions) {}

void OpalLight::sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) {
    if (*dirtyBits != hd::Dirty::Clean) {
        const hd::LightDesc desc = scene.light(id());
        if (desc.kind != kind_)
            throw Error("light '" + id() + "': a " + lightKindName(kind_) + " light prim was described as a " +
                        lightKindName(desc.kind) + " light");
        std::shared_ptr<const LatLongMap> map;
        std::shared_ptr<const LoadedShadowField> field;
        try {
            // Cached by file (and color space): editing intensity or a transform reads nothing.
            if (kind_ == hd::LightKind::Dome) map = textures_.get(desc.textureFile, desc.textureColorSpace);
            if (kind_ == hd::LightKind::ShadowField) field = fields_.get(desc.shadowField);
        } catch (const Error& e) {
            throw Error("light '" + id() + "': " + e.what());
        }
        build(desc, std::move(map), std::move(field));
    }
    *dirtyBits = hd::Dirty::Clean;
}

void OpalLight::reloadTexture() {
    if (kind_ != hd::LightKind::Dome || version_ == 0) return;
    std::shared_ptr<const LatLongMap> map;
    try {
        map = textures_.get(desc_.textureFile, desc_.textureColorSpace);
    } catch (const Error& e) {
        throw Error("light '" + id() + "': " + e.what());
    }
    build(desc_, std::move(map), nullptr);
}

void OpalLight::build(const hd::LightDesc& desc, std::shared_ptr<const LatLongMap> map,
                      std::shared_ptr<const LoadedShadowField> field) {
    try {
        if (kind_ == hd::LightKind::ShadowField) {
            field_ = std::make_shared<const ShadowFieldLight>(std::move(field), desc);
        } else if (kind_ == hd::LightKind::Dome) {
            auto environment = std::make_shared<const EnvironmentLight>(EnvironmentLight::fromDesc(map, desc));
            domeFromWorld_ = rotationOf(desc.transform, "transform").transposed();
            domeScale_ = environment->scale();
            environment_ = std::move(environment);
            map_ = std::move(map);
        } else {
            analytic_ = AnalyticLight::fromDesc(desc);
        }
    } catch (const Error& e) {
        throw Error("light '" + id() + "': " + e.what());
    }
    desc_ = desc;
    version_ = versions_.next();
}

}  // namespace opal
