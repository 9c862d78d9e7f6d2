#include "schema/usd/usda_metadata.h"

#include <algorithm>

namespace opal::usda {
namespace {

constexpr unsigned L = static_cast<unsigned>(MetadataOwner::Layer);
constexpr unsigned P = static_cast<unsigned>(MetadataOwner::Prim);
constexpr unsigned A = static_cast<unsigned>(MetadataOwner::Attribute);
constexpr unsigned R = static_cast<unsigned>(MetadataOwner::Relationship);

constexpr MetadataField kFields[] = {
    {"doc", "documentation", types::String, L | P | A | R},
    {"customData", "customData", types::Dictionary, P | A | R},
    {"defaultPrim", "defaultPrim", types::Token, L},
    {"upAxis", "upAxis", types::Token, L},
    {"metersPerUnit", "metersPerUnit", types::Double, L},
    {"kilogramsPerUnit", "kilogramsPerUnit", types::Double, L},
    {"startTimeCode", "startTimeCode", types::Double, L},
    {"endTimeCode", "endTimeCode", types::Double, L},
    {"timeCodesPerSecond", "timeCodesPerSecond", types::Double, L},
    {"framesPerSecond", "framesPerSecond", types::Double, L},
    {"customLayerData", "customLayerData", types::Dictionary, L},
    {"subLayers", "subLayers", types::AssetArray, L, true},
    {"kind", "kind", types::Token, P},
    {"active", "active", types::Bool, P},
    {"instanceable", "instanceable", types::Bool, P},
    {"assetInfo", "assetInfo", types::Dictionary, P},
    {"apiSchemas", "apiSchemas", types::TokenArray, P, true},
    {"references", "references", types::AssetArray, P, true},
    {"inherits", "inheritPaths", types::String, P, true},
    {"hidden", "hidden", types::Bool, P | A | R},
    {"displayName", "displayName", types::String, P | A | R},
    {"displayGroup", "displayGroup", types::String, A | R},
    {"interpolation", "interpolation", types::Token, A},
    {"elementSize", "elementSize", types::Int, A},
    {"allowedTokens", "allowedTokens", types::TokenArray, A},
    {"colorSpace", "colorSpace", types::Token, A},
    {"connectability", "connectability", types::Token, A},
    {"renderType", "renderType", types::Token, A},
    {"bindMaterialAs", "bindMaterialAs", types::Token, R},
};

constexpr std::string_view kUnsupported[] = {
    "payload",     "variants",          "variantSets",         "specializes", "relocates",
    "prefixSubstitutions", "suffixSubstitutions", "permission", "symmetryFunction",
    "clips",       "clipSets",          "timeSamples",         "connectionPaths", "targetPaths",
    "displayUnit", "expressionVariables",
};

}  // namespace

const MetadataField* findMetadataField(std::string_view key, MetadataOwner owner) {
    for (const MetadataField& f : kFields) {
        if (f.key == key && (f.owners & static_cast<unsigned>(owner)) != 0) {
            return &f;
        }
    }
    return nullptr;
}

bool isUnsupportedMetadata(std::string_view key) {
    return std::find(std::begin(kUnsupported), std::end(kUnsupported), key) != std::end(kUnsupported);
}

std::string_view ownerName(MetadataOwner owner) {
    switch (owner) {
        case MetadataOwner::Layer: return "layer";
        case MetadataOwner::Prim: return "prim";
        case MetadataOwner::Attribute: return "attribute";
        case MetadataOwner::Relationship: return "relationship";
    }
    return "?";
}

}  // namespace opal::usda
