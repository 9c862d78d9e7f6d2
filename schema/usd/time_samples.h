// Attribute values at a time code, as UsdAttribute::Get(time) resolves one layer's
// opinions (docs/ARCHITECTURE.md#time):
//   - authored time samples win over the default;
//   - before the first sample and after the last, the end sample holds;
//   - between two samples, floating-point scalars, vectors, colours and matrices (and
//     arrays of them of equal length) interpolate linearly, component by component, and
//     quaternions spherically (UsdStage's default, linear interpolation); every other
//     type, and arrays of unequal length, hold the earlier sample;
//   - a None sample blocks the attribute from its time until the next sample (the span
//     after it, and a span that ends at it, hold the earlier sample as USD does).
#pragma once

#include "schema/usd/usda_layer.h"

#include <optional>

namespace opal::usda {

// The value at `timeCode` (may be None); nullopt when the attribute has neither samples
// nor a default.
std::optional<Value> valueAt(const Attribute& attribute, double timeCode);

// The attribute as it reads at `timeCode`: that value as its default, no samples.
Attribute attributeAt(const Attribute& attribute, double timeCode);

// The prim's own properties at `timeCode` (everything else copied, children left out).
Prim propertiesAt(const Prim& prim, double timeCode);

// Any of the prim's own attributes has time samples (one or more).
bool hasTimeSamples(const Prim& prim);

// More than one time sample (UsdAttribute::ValueMightBeTimeVarying).
bool mightBeTimeVarying(const Attribute& attribute);
// Any of the prim's own attributes might be.
bool mightBeTimeVarying(const Prim& prim);

}  // namespace opal::usda
