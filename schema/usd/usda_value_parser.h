// Parses USDA values of a known type from the token stream: numbers (std::from_chars,
// range-checked, no inf/nan), bools, quoted strings and tokens, asset paths, tuples
// (x, y, z), matrices ((..), (..), (..), (..)), arrays [...] and dictionaries { ... }.
// Array elements are parsed straight into typed vectors.
#pragma once

#include "schema/usd/usda_lexer.h"
#include "schema/usd/usda_value.h"

namespace opal::usda {

class ValueParser {
public:
    // Dictionaries nested deeper than this are rejected (never crash on hostile input).
    static constexpr int kMaxDictionaryDepth = 32;

    explicit ValueParser(Lexer& lexer) : lex_(lexer) {}

    // A value of `type`; `None` is accepted only when allowNone (attribute defaults).
    Value parse(ValueType type, bool allowNone = false, int depth = 0);

private:
    template <ScalarType S>
    Value parseTyped(bool isArray, int depth, SourceLocation where);
    template <ScalarType S>
    void parseElement(typename ScalarStorage<S>::type& out, int depth);
    template <class T>
    void parseComponent(T& out);
    template <class E, std::size_t N>
    void parseTuple(std::array<E, N>& out);
    template <class T>
    void parseInteger(T& out, ValueType type);
    template <class T>
    void parseFloat(T& out, ValueType type);
    void parseBool(bool& out);
    std::string parseQuoted();
    std::string parseAssetPath();
    Dictionary parseDictionary(int depth);
    void parseDictionaryEntry(Dictionary& dict, int depth);
    // `expected` says what should have come; it is called only on failure, so that
    // million-element arrays build no message strings.
    template <class Expected>
    Token expect(char punct, Expected&& expected);
    Token numberToken(ValueType type);

    Lexer& lex_;
};

}  // namespace opal::usda
