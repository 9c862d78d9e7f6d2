#include "schema/usd/usda_value_parser.h"

#include "schema/usd/usda_syntax.h"

#include <charconv>
#include <type_traits>

namespace opal::usda {
namespace {

enum class NumberShape { Integer, Decimal, NonFinite, Malformed };

std::size_t skipDigits(std::string_view s, std::size_t i) {
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
        ++i;
    }
    return i;
}

// -?(digits(.digits?)?|.digits)([eE][+-]?digits)?
NumberShape classify(std::string_view s) {
    std::string_view unsigned_ = s.starts_with('-') ? s.substr(1) : s;
    if (unsigned_ == "inf" || unsigned_ == "nan" || unsigned_ == "infinity") {
        return NumberShape::NonFinite;
    }
    std::size_t i = s.starts_with('-') ? 1 : 0;
    std::size_t intEnd = skipDigits(s, i);
    bool decimal = false;
    std::size_t fracEnd = intEnd;
    if (fracEnd < s.size() && s[fracEnd] == '.') {
        decimal = true;
        fracEnd = skipDigits(s, fracEnd + 1);
    }
    if (fracEnd == i || (intEnd == i && fracEnd == intEnd + 1)) {
        return NumberShape::Malformed;  // no digits at all
    }
    if (fracEnd < s.size() && (s[fracEnd] == 'e' || s[fracEnd] == 'E')) {
        decimal = true;
        std::size_t expStart = fracEnd + 1;
        if (expStart < s.size() && (s[expStart] == '+' || s[expStart] == '-')) {
            ++expStart;
        }
        fracEnd = skipDigits(s, expStart);
        if (fracEnd == expStart) {
            return NumberShape::Malformed;
        }
    }
    if (fracEnd != s.size()) {
        return NumberShape::Malformed;
    }
    return decimal ? NumberShape::Decimal : NumberShape::Integer;
}

constexpr std::string_view kSubsetNote = " (Opal's USDA subset: see schema/usd/SUBSET.md)";

}  // namespace

template <class Expected>
Token ValueParser::expect(char punct, Expected&& expected) {
    Token t = lex_.next();
    if (!t.is(punct)) {
        if constexpr (std::is_invocable_v<Expected>) {
            lex_.unexpected(t, expected());
        } else {
            lex_.unexpected(t, expected);
        }
    }
    return t;
}

Value ValueParser::parse(ValueType type, bool allowNone, int depth) {
    const Token& first = lex_.peek();
    SourceLocation where = lex_.where(first);
    if (first.isWord("None")) {
        if (!allowNone) {
            lex_.unexpected(first, "a value of type " + typeName(type) + " (None is only accepted as an attribute value)");
        }
        lex_.next();
        return Value::none(type, where);
    }
    return visitScalarType(type.scalar, [&]<ScalarType S>() {
        return parseTyped<S>(type.isArray, depth, std::move(where));
    });
}

template <ScalarType S>
Value ValueParser::parseTyped(bool isArray, int depth, SourceLocation where) {
    using Element = typename ScalarStorage<S>::type;
    constexpr ValueType scalarType{S, false};
    if (!isArray) {
        Element element{};
        parseElement<S>(element, depth);
        return Value::make<scalarType>(std::move(element), std::move(where));
    }
    if constexpr (S == ScalarType::Dictionary) {
        lex_.fail(lex_.peek(), "dictionary arrays are not supported");
    } else {
        static constexpr ValueType arrayType{S, true};  // static: captureless lambdas below name it
        expect('[', [] { return "'[' to start a value of type " + typeName(arrayType); });
        std::vector<Element> elements;
        while (!lex_.peek().is(']')) {
            Element element{};
            parseElement<S>(element, depth);
            elements.push_back(std::move(element));
            if (!lex_.peek().is(']')) {
                expect(',', [] { return "',' or ']' in a " + typeName(arrayType) + " array"; });
            }
        }
        lex_.next();
        return Value::make<arrayType>(std::move(elements), std::move(where));
    }
}

template <ScalarType S>
void ValueParser::parseElement(typename ScalarStorage<S>::type& out, int depth) {
    using Element = typename ScalarStorage<S>::type;
    if constexpr (S == ScalarType::Dictionary) {
        out = parseDictionary(depth);
    } else if constexpr (S == ScalarType::Asset) {
        out = parseAssetPath();
    } else if constexpr (std::is_same_v<Element, std::string>) {
        out = parseQuoted();
    } else if constexpr (std::is_arithmetic_v<Element>) {
        if constexpr (std::is_same_v<Element, bool>) {
            parseBool(out);
        } else if constexpr (std::is_integral_v<Element>) {
            parseInteger(out, ValueType{S, false});
        } else {
            parseFloat(out, ValueType{S, false});
        }
    } else {
        parseTuple(out);
    }
}

template <class T>
void ValueParser::parseComponent(T& out) {
    if constexpr (std::is_integral_v<T>) {
        parseInteger(out, types::Int);
    } else if constexpr (std::is_same_v<T, float>) {
        parseFloat(out, types::Float);
    } else if constexpr (std::is_same_v<T, double>) {
        parseFloat(out, types::Double);
    } else {
        parseTuple(out);
    }
}

template <class E, std::size_t N>
void ValueParser::parseTuple(std::array<E, N>& out) {
    auto count = [] { return std::to_string(N); };
    expect('(', [&] { return "'(' to start a tuple of " + count() + " values"; });
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) {
            expect(',', [&] { return "',' (a tuple of " + count() + " values)"; });
        }
        parseComponent(out[i]);
    }
    expect(')', [&] { return "')' to end a tuple of " + count() + " values"; });
}

Token ValueParser::numberToken(ValueType type) {
    Token t = lex_.next();
    if (t.kind == TokenKind::Identifier && classify(t.text) == NumberShape::NonFinite) {
        t.kind = TokenKind::Number;
    }
    if (t.kind != TokenKind::Number) {
        lex_.unexpected(t, "a number (" + typeName(type) + ")");
    }
    switch (classify(t.text)) {
        case NumberShape::NonFinite:
            lex_.fail(t, "non-finite number '" + std::string(t.text) + "' is not accepted" + std::string(kSubsetNote));
        case NumberShape::Malformed:
            lex_.fail(t, "malformed number '" + std::string(t.text) + "'");
        default: break;
    }
    return t;
}

template <class T>
void ValueParser::parseInteger(T& out, ValueType type) {
    Token t = numberToken(type);
    if (classify(t.text) != NumberShape::Integer) {
        lex_.fail(t, "expected an integer (" + typeName(type) + "), found number '" + std::string(t.text) + "'");
    }
    auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), out);
    if (ec != std::errc() || end != t.text.data() + t.text.size()) {
        lex_.fail(t, "number '" + std::string(t.text) + "' is out of range for " + typeName(type));
    }
}

template <class T>
void ValueParser::parseFloat(T& out, ValueType type) {
    Token t = numberToken(type);
    auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), out);
    if (ec == std::errc::result_out_of_range) {
        lex_.fail(t, "number '" + std::string(t.text) + "' is out of range for " + typeName(type));
    }
    if (ec != std::errc() || end != t.text.data() + t.text.size()) {
        lex_.fail(t, "malformed number '" + std::string(t.text) + "'");
    }
}

void ValueParser::parseBool(bool& out) {
    Token t = lex_.next();
    if (t.isWord("true") || (t.kind == TokenKind::Number && t.text == "1")) {
        out = true;
    } else if (t.isWord("false") || (t.kind == TokenKind::Number && t.text == "0")) {
        out = false;
    } else {
        lex_.unexpected(t, "a bool (0, 1, true or false)");
    }
}

std::string ValueParser::parseQuoted() {
    Token t = lex_.next();
    if (t.kind != TokenKind::String) {
        lex_.unexpected(t, "a quoted string");
    }
    return lex_.decodeString(t);
}

std::string ValueParser::parseAssetPath() {
    Token t = lex_.next();
    if (t.kind != TokenKind::Asset) {
        lex_.unexpected(t, "an asset path @...@");
    }
    std::string path = lex_.decodeAsset(t);
    if (!isPrintable(path)) {
        lex_.fail(t, "asset path contains a control character");
    }
    return path;
}

Dictionary ValueParser::parseDictionary(int depth) {
    Token open = expect('{', "'{' to start a dictionary");
    if (depth >= kMaxDictionaryDepth) {
        lex_.fail(open, "dictionaries nested deeper than " + std::to_string(kMaxDictionaryDepth) + " levels");
    }
    Dictionary dict;
    while (!lex_.peek().is('}')) {
        parseDictionaryEntry(dict, depth);
        const Token& after = lex_.peek();
        if (after.is(';')) {
            lex_.next();
        } else if (!after.is('}') && !after.newlineBefore) {
            lex_.unexpected(after, "a newline or ';' after a dictionary entry");
        }
    }
    lex_.next();
    return dict;
}

// `type key = value`; the key is an identifier or a quoted string.
void ValueParser::parseDictionaryEntry(Dictionary& dict, int depth) {
    Token typeToken = lex_.next();
    std::optional<ValueType> type;
    if (typeToken.kind == TokenKind::Identifier) {
        type = parseTypeName(typeToken.text);
    }
    if (!type) {
        lex_.unexpected(typeToken, "a dictionary entry type (e.g. string, double, dictionary) or '}'");
    }
    Token keyToken = lex_.next();
    std::string key;
    if (keyToken.kind == TokenKind::String) {
        key = lex_.decodeString(keyToken);
    } else if (keyToken.kind == TokenKind::Identifier && isIdentifier(keyToken.text)) {
        key = std::string(keyToken.text);
    } else {
        lex_.unexpected(keyToken, "a dictionary key (identifier or quoted string)");
    }
    expect('=', [&] { return "'=' after dictionary key '" + key + "'"; });
    Value value = parse(*type, false, depth + 1);
    if (!dict.insert(key, std::move(value))) {
        lex_.fail(keyToken, "duplicate dictionary key '" + key + "'");
    }
}


}  // namespace opal::usda
