// The USDA tokenizer: splits text into identifiers (namespaced, with an optional "[]"
// type suffix), numbers, quoted strings, asset paths @...@, paths <...> and
// punctuation, skipping whitespace and # comments. Tokens are views into the text (no
// copies: million-element arrays stay fast); each knows its line, column and whether a
// newline preceded it (USDA separates statements by newlines or ';').
#pragma once

#include "schema/usd/usda_location.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace opal::usda {

enum class TokenKind { End, Identifier, Number, String, Asset, Path, Punct };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  // raw source text, quotes and delimiters included
    int line = 0;
    int column = 0;
    bool newlineBefore = false;

    bool is(char punct) const { return kind == TokenKind::Punct && text.size() == 1 && text[0] == punct; }
    bool isWord(std::string_view word) const { return kind == TokenKind::Identifier && text == word; }
};

class Lexer {
public:
    Lexer(std::string_view text, std::shared_ptr<const std::string> file);

    // Checks and skips the required first line "#usda 1.0".
    void readHeader();

    const Token& peek();
    Token next();

    SourceLocation where(const Token& t) const { return {file_, t.line, t.column}; }
    [[noreturn]] void fail(const Token& t, const std::string& message) const;
    // "unexpected '}', expected '='"
    [[noreturn]] void unexpected(const Token& t, std::string_view expected) const;

    // The contents of String, Asset and Path tokens, escapes resolved. Strings and asset
    // paths must be well-formed UTF-8 without NUL bytes (escaped or not); the error names
    // the line and column of the offending byte or escape.
    std::string decodeString(const Token& t) const;
    std::string decodeAsset(const Token& t) const;
    std::string_view pathText(const Token& t) const { return t.text.substr(1, t.text.size() - 2); }

private:
    Token scan();
    bool skipSpaceAndComments();  // true if a newline was crossed
    void newline();
    void scanIdentifier();
    void scanNumber();
    void scanString(const Token& start);
    void scanAsset(const Token& start);
    void scanPath(const Token& start);
    // Fails at t.text[offset], saying what is wrong with text[bad] (NUL or not UTF-8).
    [[noreturn]] void failInText(const Token& t, std::size_t offset, std::string_view text, std::size_t bad,
                                 std::string_view what) const;
    char at(std::size_t i) const { return i < text_.size() ? text_[i] : '\0'; }
    int column() const { return static_cast<int>(pos_ - lineStart_) + 1; }

    std::string_view text_;
    std::shared_ptr<const std::string> file_;
    std::size_t pos_ = 0;
    std::size_t lineStart_ = 0;
    int line_ = 1;
    std::optional<Token> peeked_;
};

// How a token is named in messages: 'def', '}', string "abc", end of file.
std::string describe(const Token& t);

}  // namespace opal::usda
