// Formats one Value in USDA syntax, as Sdf writes it: shortest round-trip numbers,
// tuples (x, y, z), matrices ( (..), (..), (..), (..) ), arrays on one line, strings
// quoted by Sdf's rules, asset paths @...@, dictionaries one entry per line sorted by key.
#pragma once

#include "schema/usd/usda_value.h"

#include <string>
#include <string_view>

namespace opal::usda {

// Sdf writes bools in metadata fields as true/false and everywhere else (attribute
// values, dictionary entries) as 1/0.
enum class BoolStyle { Digits, Words };

// Appends `value`; a dictionary's closing brace goes at `indent` (4 spaces per level).
// Throws opal::Error naming `context` for what USDA cannot carry (non-finite numbers,
// control characters in asset paths).
void appendValue(std::string& out, const Value& value, int indent, BoolStyle style, std::string_view context);

void appendIndent(std::string& out, int indent);

}  // namespace opal::usda
