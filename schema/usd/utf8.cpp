#include "schema/usd/utf8.h"

namespace opal::usda {
namespace {

struct LeadRule {
    unsigned char lo, hi;          // range of the lead byte
    int length;                    // bytes in the sequence
    unsigned char secondLo, secondHi;  // range allowed for the second byte
};

// Unicode Table 3-7; the second byte's range excludes overlongs, surrogates and > U+10FFFF.
constexpr LeadRule kRules[] = {
    {0xC2, 0xDF, 2, 0x80, 0xBF}, {0xE0, 0xE0, 3, 0xA0, 0xBF}, {0xE1, 0xEC, 3, 0x80, 0xBF},
    {0xED, 0xED, 3, 0x80, 0x9F}, {0xEE, 0xEF, 3, 0x80, 0xBF}, {0xF0, 0xF0, 4, 0x90, 0xBF},
    {0xF1, 0xF3, 4, 0x80, 0xBF}, {0xF4, 0xF4, 4, 0x80, 0x8F},
};

bool inRange(unsigned char c, unsigned char lo, unsigned char hi) { return c >= lo && c <= hi; }

}  // namespace

int utf8SequenceLength(std::string_view s) {
    if (s.empty()) {
        return 0;
    }
    auto lead = static_cast<unsigned char>(s[0]);
    if (lead < 0x80) {
        return 1;
    }
    for (const LeadRule& rule : kRules) {
        if (!inRange(lead, rule.lo, rule.hi)) {
            continue;
        }
        if (s.size() < static_cast<std::size_t>(rule.length) ||
            !inRange(static_cast<unsigned char>(s[1]), rule.secondLo, rule.secondHi)) {
            return 0;
        }
        for (int j = 2; j < rule.length; ++j) {
            if (!inRange(static_cast<unsigned char>(s[static_cast<std::size_t>(j)]), 0x80, 0xBF)) {
                return 0;
            }
        }
        return rule.length;
    }
    return 0;
}

std::size_t firstBadTextByte(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        int n = utf8SequenceLength(s.substr(i));
        if (n == 0 || s[i] == '\0') {
            return i;
        }
        i += static_cast<std::size_t>(n);
    }
    return std::string_view::npos;
}

}  // namespace opal::usda
