// The metadata fields Opal's USDA subset accepts, per owner (layer, prim, attribute,
// relationship), each with its value type and the Sdf field name the writer sorts by
// (Sdf writes metadata in dictionary order of field names: `doc` sorts as
// "documentation", `inherits` as "inheritPaths").
#pragma once

#include "schema/usd/usda_type.h"

#include <string_view>

namespace opal::usda {

enum class MetadataOwner : unsigned { Layer = 1, Prim = 2, Attribute = 4, Relationship = 8 };

struct MetadataField {
    std::string_view key;      // as written: "doc"
    std::string_view sortKey;  // Sdf field name: "documentation"
    ValueType type;
    unsigned owners;           // MetadataOwner bits
    bool listOp = false;       // apiSchemas, references: parsed and stored by the reader itself
};

// The field with this key that `owner` may carry, or nullptr.
const MetadataField* findMetadataField(std::string_view key, MetadataOwner owner);
// Where a key names a USD feature outside the subset (payload, variants, ...).
bool isUnsupportedMetadata(std::string_view key);
std::string_view ownerName(MetadataOwner owner);  // "layer", "prim", ...

}  // namespace opal::usda
