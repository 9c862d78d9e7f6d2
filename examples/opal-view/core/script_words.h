// Splits one line of an opal-view script into words: spaces separate, double quotes keep
// spaces inside one word, '#' outside quotes starts a comment.
#pragma once

#include <string>
#include <vector>

namespace opal::view {

// Throws opal::Error (without location: the caller adds FILE:LINE) for an unclosed quote.
std::vector<std::string> splitScriptWords(const std::string& line);

}  // namespace opal::view
