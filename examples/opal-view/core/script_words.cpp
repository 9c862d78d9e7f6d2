#include "examples/opal-view/core/script_words.h"

#include "schema/error.h"

namespace opal::view {

std::vector<std::string> splitScriptWords(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    bool quoted = false, inWord = false;
    for (const char c : line) {
        if (quoted) {
            if (c == '"') quoted = false;
            else word += c;
            continue;
        }
        if (c == '#') break;
        if (c == ' ' || c == '\t' || c == '\r') {
            if (inWord) words.push_back(std::move(word));
            word.clear();
            inWord = false;
            continue;
        }
        inWord = true;
        if (c == '"') quoted = true;
        else word += c;
    }
    if (quoted) throw Error("unclosed double quote");
    if (inWord) words.push_back(std::move(word));
    return words;
}

}  // namespace opal::view
