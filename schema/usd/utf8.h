// Well-formed UTF-8 as Unicode defines it (Table 3-7: no overlong forms, no surrogates,
// nothing above U+10FFFF). USDA text is UTF-8; strings, tokens, asset paths and names
// must be well-formed and hold no NUL byte, which USD's C strings would cut short.
#pragma once

#include <cstddef>
#include <string_view>

namespace opal::usda {

// Length (1-4) of the well-formed UTF-8 sequence at the start of s; 0 if s is empty or
// does not start with one.
int utf8SequenceLength(std::string_view s);

// Offset of the first NUL byte or the first byte not part of a well-formed UTF-8
// sequence; npos when the text is clean.
std::size_t firstBadTextByte(std::string_view s);

}  // namespace opal::usda
