#include "schema/usd/usda_syntax.h"

#include "schema/usd/utf8.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>

namespace opal::usda {
namespace {

bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Length of the identifier at the start of s (0 if none).
std::size_t identifierLength(std::string_view s) {
    if (s.empty() || !isIdentifierStart(s[0])) {
        return 0;
    }
    std::size_t n = 1;
    while (n < s.size() && isIdentifierChar(s[n])) {
        ++n;
    }
    return n;
}

// Consumes "../" repetitions; returns how many characters they took.
std::size_t parentPrefixLength(std::string_view s) {
    std::size_t n = 0;
    while (s.substr(n).starts_with("..")) {
        n += 2;
        if (n < s.size() && s[n] == '/') {
            ++n;
        } else {
            break;
        }
    }
    return n;
}

void appendEscaped(std::string& out, char c, char quote, bool triple) {
    static constexpr char kHex[] = "0123456789abcdef";
    auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
        out += triple ? "\n" : "\\n";
    } else if (c == '\r') {
        out += "\\r";
    } else if (c == '\t') {
        out += "\\t";
    } else if (c == '\\') {
        out += "\\\\";
    } else if (c == quote) {
        out += '\\';
        out += quote;
    } else if (u < 32 || u > 126) {
        out += "\\x";
        out += kHex[u >> 4];
        out += kHex[u & 15];
    } else {
        out += c;
    }
}

// Shortest round-trip digits and decimal exponent of v (v = 0.d1d2... * 10^pointPos).
struct ShortestDigits {
    bool negative = false;
    char digits[32] = {};
    int count = 0;
    int pointPos = 0;
};

template <class T>
ShortestDigits shortestDigits(T v) {
    char buf[64];
    char* end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific).ptr;
    ShortestDigits d;
    const char* p = buf;
    if (*p == '-') {
        d.negative = true;
        ++p;
    }
    for (; p < end && *p != 'e'; ++p) {
        if (*p != '.') {
            d.digits[d.count++] = *p;
        }
    }
    int exponent = 0;
    std::from_chars(p + (p[1] == '+' ? 2 : 1), end, exponent);
    d.pointPos = exponent + 1;
    return d;
}

// ECMAScript Number::toString layout of shortest digits.
void appendLayout(std::string& out, const ShortestDigits& d) {
    const std::string_view s(d.digits, static_cast<std::size_t>(d.count));
    const int k = d.count;
    const int n = d.pointPos;
    if (d.negative) {
        out += '-';
    }
    if (k <= n && n <= 21) {
        out += s;
        out.append(static_cast<std::size_t>(n - k), '0');
    } else if (0 < n && n <= 21) {
        out += s.substr(0, static_cast<std::size_t>(n));
        out += '.';
        out += s.substr(static_cast<std::size_t>(n));
    } else if (-6 < n && n <= 0) {
        out += "0.";
        out.append(static_cast<std::size_t>(-n), '0');
        out += s;
    } else {
        out += s[0];
        if (k > 1) {
            out += '.';
            out += s.substr(1);
        }
        out += n - 1 >= 0 ? "e+" : "e-";
        appendNumber(out, static_cast<std::int64_t>(std::abs(n - 1)));
    }
}

}  // namespace

bool isIdentifier(std::string_view s) { return !s.empty() && identifierLength(s) == s.size(); }

bool isNamespacedName(std::string_view s) {
    while (true) {
        std::size_t n = identifierLength(s);
        if (n == 0) {
            return false;
        }
        if (n == s.size()) {
            return true;
        }
        if (s[n] != ':') {
            return false;
        }
        s.remove_prefix(n + 1);
    }
}

bool isPath(std::string_view s) {
    std::size_t pos = 0;
    if (s.starts_with('/')) {
        pos = 1;
    } else {
        pos = parentPrefixLength(s);
        if (pos == s.size() && pos > 0) {
            return true;  // "..", "../.."
        }
    }
    if (pos > 0 && s[pos - 1] != '/' && s[pos] != '.') {
        return false;
    }
    while (true) {
        std::size_t n = identifierLength(s.substr(pos));
        if (n == 0) {
            return false;
        }
        pos += n;
        if (pos == s.size()) {
            return true;
        }
        if (s[pos] == '.') {
            return isNamespacedName(s.substr(pos + 1));
        }
        if (s[pos] != '/') {
            return false;
        }
        ++pos;
    }
}

bool isPrintable(std::string_view s) {
    return std::none_of(s.begin(), s.end(), [](char c) {
        auto u = static_cast<unsigned char>(c);
        return u < 32 || u == 127;
    });
}

std::string quoteString(std::string_view s) {
    char quote = s.find('"') != std::string_view::npos && s.find('\'') == std::string_view::npos ? '\'' : '"';
    bool triple = s.find('\n') != std::string_view::npos;
    std::string out(triple ? 3 : 1, quote);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (int n = utf8SequenceLength(s.substr(i)); n > 1) {
            out += s.substr(i, static_cast<std::size_t>(n));
            i += static_cast<std::size_t>(n) - 1;
        } else {
            appendEscaped(out, s[i], quote, triple);
        }
    }
    out.append(triple ? 3 : 1, quote);
    return out;
}

std::string quoteAssetPath(std::string_view s) {
    if (s.find('@') == std::string_view::npos) {
        std::string out(1, '@');
        out += s;
        return out + "@";
    }
    std::string out = "@@@";
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.substr(i).starts_with("@@@")) {
            out += "\\@@@";
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out + "@@@";
}

void appendNumber(std::string& out, float v) { appendLayout(out, shortestDigits(v)); }
void appendNumber(std::string& out, double v) { appendLayout(out, shortestDigits(v)); }

void appendNumber(std::string& out, std::int64_t v) {
    char buf[24];
    out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

void appendNumber(std::string& out, std::uint64_t v) {
    char buf[24];
    out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

bool dictionaryLess(std::string_view a, std::string_view b) {
    auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
    auto [ia, ib] = std::mismatch(a.begin(), a.end(), b.begin(), b.end(),
                                  [&](char x, char y) { return lower(x) == lower(y); });
    if (ia == a.end() || ib == b.end()) {
        return a.size() != b.size() ? a.size() < b.size() : a < b;
    }
    return lower(*ia) < lower(*ib);
}

}  // namespace opal::usda
