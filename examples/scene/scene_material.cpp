#include "examples/scene/scene_material.h"

#include "examples/scene/xformable.h"
#include "schema/scatter/dipole.h"
#include "schema/error.h"

namespace opal::scene {
namespace {

using usda::types::Color3f;

const Bounds AlbedoBounds{0.0, 1.0, true, true};
// The dipole's own range, so that the scene is refused where it is written.
const Bounds EtaBounds = Bounds::closed(kDipoleEtaMin, kDipoleEtaMax);

// One way of giving the subsurface coefficients: its attributes, as authored.
struct Parameterization {
    const char* description;
    std::vector<const usda::Attribute*> attributes;

    const usda::Attribute* first() const {
        for (const usda::Attribute* a : attributes)
            if (a) return a;
        return nullptr;
    }
};

Rgb colorOf(const usda::Attribute& attribute) {
    const usda::Vec3f& c = std::get<usda::Vec3f>(attribute.value->data());
    return {c[0], c[1], c[2]};
}

// The one parameterization authored; throws for none, two, or half of a pair.
const Parameterization& chooseParameterization(PrimReader& reader, const std::vector<Parameterization>& choices) {
    const Parameterization* chosen = nullptr;
    for (const Parameterization& p : choices) {
        const usda::Attribute* present = p.first();
        if (!present) continue;
        if (chosen)
            reader.failAt(*present, "conflicts with " + quotedName(chosen->first()->name) + " (at " +
                                        chosen->first()->location.str() + "): a Material takes one of opal:preset, "
                                        "opal:sigmaSPrime + opal:sigmaA, or opal:albedo + opal:meanFreePath");
        for (const usda::Attribute* a : p.attributes)
            if (!a) reader.failAt(*present, std::string("needs the rest of ") + p.description + " to be authored too");
        chosen = &p;
    }
    if (!chosen)
        reader.fail(reader.prim().location,
                    "sets no subsurface coefficients: author opal:preset, opal:sigmaSPrime and opal:sigmaA, or "
                    "opal:albedo and opal:meanFreePath (see examples/SCENES.md)");
    return *chosen;
}

Material presetMaterial(PrimReader& reader, const usda::Attribute& preset) {
    const std::string& name = std::get<std::string>(preset.value->data());
    const std::optional<Material> material = findPreset(name);
    if (!material) reader.failAt(preset, "is " + quotedName(name) + ", which is not a preset (" + presetNames() + ")");
    return *material;
}

Material artistMaterial(PrimReader& reader, const usda::Attribute& albedo, const usda::Attribute& meanFreePath,
                        double eta) {
    try {
        return fromArtist(ArtistMaterial{colorOf(albedo), colorOf(meanFreePath), eta});
    } catch (const Error& e) {
        reader.failAt(albedo, std::string("and 'opal:meanFreePath' cannot be inverted: ") + e.what());
    }
}

Material subsurface(PrimReader& reader) {
    const usda::Attribute* preset = reader.find("opal:preset", {usda::types::Token});
    // The range checks run when the attributes are read, before the pair rules apply.
    reader.color("opal:sigmaSPrime", Bounds::positive());
    reader.color("opal:sigmaA", Bounds::positive());
    reader.color("opal:albedo", AlbedoBounds);
    reader.color("opal:meanFreePath", Bounds::positive());
    const std::vector<Parameterization> choices = {
        {"opal:preset", {preset}},
        {"opal:sigmaSPrime + opal:sigmaA", {reader.find("opal:sigmaSPrime", {Color3f}), reader.find("opal:sigmaA", {Color3f})}},
        {"opal:albedo + opal:meanFreePath", {reader.find("opal:albedo", {Color3f}), reader.find("opal:meanFreePath", {Color3f})}},
    };
    const std::optional<double> eta = reader.real("opal:eta", usda::types::Float, EtaBounds);
    const Parameterization& chosen = chooseParameterization(reader, choices);
    Material material;
    if (&chosen == &choices[0]) {
        material = presetMaterial(reader, *preset);
        if (eta) material.eta = *eta;
    } else if (&chosen == &choices[1]) {
        material = Material{colorOf(*chosen.attributes[0]), colorOf(*chosen.attributes[1]), eta.value_or(Material{}.eta)};
    } else {
        material = artistMaterial(reader, *chosen.attributes[0], *chosen.attributes[1], eta.value_or(Material{}.eta));
    }
    return material;
}

}  // namespace

std::string presetNames() {
    std::string names;
    for (const NamedMaterial& preset : jensenPresets()) names += (names.empty() ? "" : ", ") + std::string(preset.name);
    return names;
}

hd::MaterialDesc readMaterial(PrimReader& reader) {
    rejectTransform(reader);
    hd::MaterialDesc desc;
    desc.subsurface = subsurface(reader);
    desc.specular = reader.get<usda::types::Bool>("opal:specular").value_or(desc.specular);
    desc.specularRoughness =
        reader.real("opal:specularRoughness", usda::types::Float, Bounds::closed(0.0, 1.0)).value_or(desc.specularRoughness);
    return desc;
}

}  // namespace opal::scene
