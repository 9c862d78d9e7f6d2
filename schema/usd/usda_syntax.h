// The lexical rules of USDA shared by the reader and the writer: what an identifier,
// a namespaced property name and a path are, how strings and asset paths are quoted
// (as Sdf_FileIOUtility::Quote does), and how numbers are printed (shortest text that
// reads back to the same float/double, ECMAScript-style choice of plain/exponent form).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace opal::usda {

// [A-Za-z_][A-Za-z0-9_]*
bool isIdentifier(std::string_view s);
// Identifiers joined by ':' ("opal:basis:K").
bool isNamespacedName(std::string_view s);
// Sdf prim or property path without < >: "/World/Mesh", "/World/Mesh.points",
// "../Sibling", "Child/Grandchild". No variant selections, no target paths.
bool isPath(std::string_view s);
// No control characters (bytes < 0x20 and 0x7f).
bool isPrintable(std::string_view s);

// "text" with \n \t \r \\ \xNN escapes; '...' if it contains " but not '; triple quotes
// (with raw newlines) if it contains a newline; valid UTF-8 sequences pass through.
std::string quoteString(std::string_view s);
// @path@, or @@@path@@@ (with "@@@" escaped) when the path contains '@'.
std::string quoteAssetPath(std::string_view s);

void appendNumber(std::string& out, float v);
void appendNumber(std::string& out, double v);
void appendNumber(std::string& out, std::int64_t v);
void appendNumber(std::string& out, std::uint64_t v);

// TfDictionaryLessThan for the ASCII keys Opal writes: case-insensitive, then by case.
bool dictionaryLess(std::string_view a, std::string_view b);

}  // namespace opal::usda
