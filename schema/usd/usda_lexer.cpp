#include "schema/usd/usda_lexer.h"

#include "schema/usd/usda_error.h"
#include "schema/usd/utf8.h"

#include <cctype>
#include <cstring>

namespace opal::usda {
namespace {

struct Unescaped {
    std::size_t offset = 0;
    bool badEscape = false;
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isAlpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isIdentifierStart(char c) { return isAlpha(c) || c == '_'; }
bool isIdentifierChar(char c) { return isIdentifierStart(c) || isDigit(c); }
bool isNumberChar(char c) { return isIdentifierChar(c) || c == '.' || c == '+' || c == '-'; }

std::string printable(char c) {
    auto u = static_cast<unsigned char>(c);
    if (u >= 32 && u < 127) {
        return std::string(1, c);
    }
    static constexpr char kHex[] = "0123456789abcdef";
    return std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
}

std::string truncated(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 40)) {
        out += c == '\n' ? std::string("\\n") : printable(c);
    }
    return s.size() > 40 ? out + "..." : out;
}

// Resolves one escape at s[i] (just after the backslash) and returns the chars consumed.
std::size_t decodeEscape(std::string_view s, std::size_t i, std::string& out) {
    static constexpr std::string_view kSimple = "abfnrtv\\'\"";
    static constexpr std::string_view kValues = "\a\b\f\n\r\t\v\\'\"";
    if (std::size_t k = kSimple.find(s[i]); k != std::string_view::npos) {
        out += kValues[k];
        return 1;
    }
    int base = s[i] == 'x' ? 16 : 8;
    std::size_t start = s[i] == 'x' ? i + 1 : i;
    std::size_t maxDigits = base == 16 ? 2 : 3;
    std::size_t n = 0;
    unsigned value = 0;
    while (n < maxDigits && start + n < s.size()) {
        char c = s[start + n];
        int digit = isDigit(c) ? c - '0' : (base == 16 && std::isxdigit(static_cast<unsigned char>(c)))
                                               ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                                               : -1;
        if (digit < 0 || digit >= base) {
            break;
        }
        value = value * static_cast<unsigned>(base) + static_cast<unsigned>(digit);
        ++n;
    }
    if (n == 0 || value > 255) {
        return 0;
    }
    out += static_cast<char>(value);
    return (start - i) + n;
}

// Resolves the escapes of a string's body into out until out holds more than `limit`
// bytes. Returns the offset in body of the piece (character or escape) that produced
// out[limit], body.size() when the body ran out first, or a bad escape's backslash.
Unescaped unescape(std::string_view body, std::string& out, std::size_t limit) {
    for (std::size_t i = 0; i < body.size(); ++i) {
        std::size_t piece = i;
        if (body[i] != '\\') {
            out += body[i];
        } else {
            std::size_t used = i + 1 < body.size() ? decodeEscape(body, i + 1, out) : 0;
            if (used == 0) {
                return {i, true};
            }
            i += used;
        }
        if (out.size() > limit) {
            return {piece, false};
        }
    }
    return {body.size(), false};
}

}  // namespace

std::string describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::End: return "end of file";
        case TokenKind::String: return "string " + truncated(t.text);
        case TokenKind::Number: return "number '" + truncated(t.text) + "'";
        default: {
            std::string quoted(1, '\'');
            quoted += truncated(t.text);
            return quoted + "'";
        }
    }
}

Lexer::Lexer(std::string_view text, std::shared_ptr<const std::string> file)
    : text_(text), file_(std::move(file)) {}

void Lexer::readHeader() {
    std::size_t end = text_.find('\n');
    std::string_view first = text_.substr(0, end);
    if (!first.empty() && first.back() == '\r') {
        first.remove_suffix(1);
    }
    Token at1{TokenKind::End, first, 1, 1, false};
    if (!first.starts_with("#usda ")) {
        fail(at1, "missing '#usda 1.0' header: the first line of a USDA layer must be '#usda 1.0'");
    }
    std::string_view version = first.substr(6);
    while (!version.empty() && (version.back() == ' ' || version.back() == '\t')) {
        version.remove_suffix(1);
    }
    if (version != "1.0") {
        at1.column = 7;
        fail(at1, "unsupported USDA version '" + truncated(version) + "', expected '1.0'");
    }
    pos_ = end == std::string_view::npos ? text_.size() : end;
}

const Token& Lexer::peek() {
    if (!peeked_) {
        peeked_ = scan();
    }
    return *peeked_;
}

Token Lexer::next() {
    Token t = peek();
    peeked_.reset();
    return t;
}

void Lexer::fail(const Token& t, const std::string& message) const { throw UsdaError(where(t), message); }

void Lexer::unexpected(const Token& t, std::string_view expected) const {
    fail(t, "unexpected " + describe(t) + ", expected " + std::string(expected));
}

void Lexer::newline() {
    ++line_;
    lineStart_ = pos_ + 1;
}

bool Lexer::skipSpaceAndComments() {
    bool sawNewline = false;
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (c == '\n') {
            newline();
            sawNewline = true;
        } else if (c == '#') {
            while (pos_ + 1 < text_.size() && text_[pos_ + 1] != '\n') {
                ++pos_;
            }
        } else if (c != ' ' && c != '\t' && c != '\r') {
            break;
        }
        ++pos_;
    }
    return sawNewline;
}

Token Lexer::scan() {
    Token t;
    t.newlineBefore = skipSpaceAndComments();
    t.line = line_;
    t.column = column();
    std::size_t start = pos_;
    if (pos_ >= text_.size()) {
        return t;
    }
    char c = text_[pos_];
    char c1 = at(pos_ + 1);
    if (isIdentifierStart(c)) {
        t.kind = TokenKind::Identifier;
        scanIdentifier();
    } else if (isDigit(c) || (c == '-' && (isNumberChar(c1) && c1 != '-' && c1 != '+')) || (c == '.' && isDigit(c1))) {
        t.kind = TokenKind::Number;
        scanNumber();
    } else if (c == '"' || c == '\'') {
        t.kind = TokenKind::String;
        scanString(t);
    } else if (c == '@') {
        t.kind = TokenKind::Asset;
        scanAsset(t);
    } else if (c == '<') {
        t.kind = TokenKind::Path;
        scanPath(t);
    } else if (c != '\0' && std::strchr("()[]{},=;.:", c) != nullptr) {  // strchr finds the terminator
        t.kind = TokenKind::Punct;
        ++pos_;
    } else {
        fail(t, "unexpected character '" + printable(c) + "'");
    }
    t.text = text_.substr(start, pos_ - start);
    return t;
}

void Lexer::scanIdentifier() {
    while (true) {
        while (isIdentifierChar(at(pos_))) {
            ++pos_;
        }
        if (at(pos_) != ':' || !isIdentifierStart(at(pos_ + 1))) {
            break;
        }
        ++pos_;
    }
    if (at(pos_) == '[' && at(pos_ + 1) == ']') {
        pos_ += 2;
    }
}

void Lexer::scanNumber() {
    ++pos_;
    while (isNumberChar(at(pos_))) {
        ++pos_;
    }
}

void Lexer::scanString(const Token& start) {
    char quote = text_[pos_];
    bool triple = at(pos_ + 1) == quote && at(pos_ + 2) == quote;
    pos_ += triple ? 3 : 1;
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (c == '\\' && at(pos_ + 1) != '\n') {
            pos_ += 2;
            continue;
        }
        if (c == '\\') {
            ++pos_;  // a backslash before a newline: the escape is rejected when decoded
            c = '\n';
        }
        if (c == '\n') {
            if (!triple) {
                break;
            }
            newline();
        } else if (c == quote && (!triple || (at(pos_ + 1) == quote && at(pos_ + 2) == quote))) {
            pos_ += triple ? 3 : 1;
            return;
        }
        ++pos_;
    }
    fail(start, triple ? "unterminated triple-quoted string" : "unterminated string (strings end on the same line)");
}

void Lexer::scanAsset(const Token& start) {
    bool triple = at(pos_ + 1) == '@' && at(pos_ + 2) == '@';
    pos_ += triple ? 3 : 1;
    while (pos_ < text_.size() && text_[pos_] != '\n') {
        if (triple && text_[pos_] == '\\' && text_.substr(pos_ + 1).starts_with("@@@")) {
            pos_ += 4;
            continue;
        }
        if (!triple && text_[pos_] == '@') {
            ++pos_;
            return;
        }
        if (triple && text_.substr(pos_).starts_with("@@@") && at(pos_ + 3) != '@') {
            pos_ += 3;
            return;
        }
        ++pos_;
    }
    fail(start, "unterminated asset path (asset paths end on the same line)");
}

void Lexer::scanPath(const Token& start) {
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') {
        if (text_[pos_++] == '>') {
            return;
        }
    }
    fail(start, "unterminated path (expected '>' on the same line)");
}

std::string Lexer::decodeString(const Token& t) const {
    std::size_t delimiter = t.text.size() >= 6 && t.text[1] == t.text[0] && t.text[2] == t.text[0] ? 3 : 1;
    std::string_view body = t.text.substr(delimiter, t.text.size() - 2 * delimiter);
    std::string out;
    out.reserve(body.size());
    Unescaped done = unescape(body, out, std::string::npos);
    if (done.badEscape) {
        std::size_t i = done.offset;
        fail(t, "invalid escape sequence '\\" + (i + 1 < body.size() ? printable(body[i + 1]) : "") + "' in string");
    }
    if (std::size_t bad = firstBadTextByte(out); bad != std::string::npos) {
        std::string probe;
        std::size_t source = unescape(body, probe, bad).offset;
        failInText(t, delimiter + source, out, bad, "string");
    }
    return out;
}

std::string Lexer::decodeAsset(const Token& t) const {
    bool triple = t.text.starts_with("@@@") && t.text.size() >= 6;
    std::size_t delimiter = triple ? 3 : 1;
    std::string_view body = t.text.substr(delimiter, t.text.size() - 2 * delimiter);
    // Escapes (\@@@) only produce '@', so the raw body is clean exactly when the path is.
    if (std::size_t bad = firstBadTextByte(body); bad != std::string::npos) {
        failInText(t, delimiter + bad, body, bad, "asset path");
    }
    std::string out;
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (triple && body.substr(i).starts_with("\\@@@")) {
            out += "@@@";
            i += 3;
        } else {
            out += body[i];
        }
    }
    return out;
}

void Lexer::failInText(const Token& t, std::size_t offset, std::string_view text, std::size_t bad,
                       std::string_view what) const {
    Token at = t;
    for (std::size_t i = 0; i < offset; ++i) {
        if (t.text[i] == '\n') {
            ++at.line;
            at.column = 0;
        }
        ++at.column;
    }
    if (text[bad] == '\0') {
        fail(at, std::string(what) + " contains a NUL byte");
    }
    fail(at, std::string(what) + " is not valid UTF-8 (byte " + printable(text[bad]) + ")");
}

}  // namespace opal::usda
