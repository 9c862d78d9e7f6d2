#include "schema/usd/usda_reader.h"

#include "schema/usd/usda_error.h"
#include "schema/usd/usda_lexer.h"
#include "schema/usd/usda_metadata.h"
#include "schema/usd/usda_syntax.h"
#include "schema/usd/usda_value_parser.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <unordered_map>

namespace opal::usda {
namespace {

constexpr std::string_view kSubsetNote = " (Opal's USDA subset: see schema/usd/SUBSET.md)";

bool isSpecifier(const Token& t) { return t.isWord("def") || t.isWord("over") || t.isWord("class"); }

bool isListOpKeyword(const Token& t) {
    return t.isWord("prepend") || t.isWord("append") || t.isWord("delete") || t.isWord("add") ||
           t.isWord("reorder");
}

Specifier specifierOf(const Token& t) {
    return t.isWord("def") ? Specifier::Def : t.isWord("over") ? Specifier::Over : Specifier::Class;
}

// Names already used in one scope (metadata keys, sibling prims, properties), with
// where they were first used, to reject duplicates.
class NameScope {
public:
    explicit NameScope(std::string_view what) : what_(what) {}
    void add(Lexer& lex, const Token& at, const std::string& name) {
        auto [it, inserted] = first_.try_emplace(name, at.line, at.column);
        if (!inserted) {
            lex.fail(at, "duplicate " + what_ + " '" + name + "' (first at " + std::to_string(it->second.first) +
                             ":" + std::to_string(it->second.second) + ")");
        }
    }
    bool contains(const std::string& name) const { return first_.contains(name); }

private:
    std::string what_;
    std::unordered_map<std::string, std::pair<int, int>> first_;
};

class Parser {
public:
    Parser(std::string_view text, std::shared_ptr<const std::string> file)
        : lex_(text, file), values_(lex_), file_(std::move(file)) {}

    Layer parseLayer();

private:
    // Metadata blocks: '(' entries separated by newlines or ';' ')'.
    template <class Entry>
    void parseMetadataBlock(Entry&& entry);
    void parseLayerMetadataEntry(Layer& layer, NameScope& seen);
    void parsePrimMetadataEntry(Prim& prim, NameScope& seen);
    void parsePropertyMetadataEntry(Dictionary& metadata, std::string& comment, MetadataOwner owner,
                                    NameScope& seen);
    void parseComment(std::string& comment, NameScope& seen);
    void parseGenericMetadata(Dictionary& metadata, MetadataOwner owner, NameScope& seen);
    void parseSubLayers(Layer& layer, NameScope& seen);
    void parseListOpStatement(Prim& prim, NameScope& seen);
    void parseInherits(Prim& prim, NameScope& seen);
    std::vector<std::string> parseTokenList();
    std::vector<Reference> parseReferenceList();
    Reference parseReference();

    // Prims and properties.
    Prim parsePrim(int depth);
    void parsePrimBody(Prim& prim, int depth);
    void addProperty(Prim& prim, Property property, const Token& at, NameScope& declared, NameScope& sampled);
    void rejectBodyKeyword(const Token& t);
    Property parseProperty();
    Attribute parseAttribute(bool custom, bool uniform, const Token& first);
    Relationship parseRelationship(bool custom, const Token& first);
    std::vector<std::string> parseTargets();
    std::string parsePath(std::string_view what, bool primOnly);
    Token parsePropertyName(std::string_view what, bool* timeSamples = nullptr);
    std::vector<TimeSample> parseTimeSamples(ValueType type);

    // Helpers.
    Token expect(char punct, std::string_view expected);
    void separator(char closing, std::string_view after);
    [[noreturn]] void unsupported(const Token& at, std::string_view construct);

    Lexer lex_;
    ValueParser values_;
    std::shared_ptr<const std::string> file_;
};

Layer Parser::parseLayer() {
    lex_.readHeader();
    Layer layer;
    layer.location = SourceLocation{file_, 0, 0};
    if (lex_.peek().is('(')) {
        NameScope seen("layer metadata");
        parseMetadataBlock([&] { parseLayerMetadataEntry(layer, seen); });
    }
    NameScope roots("root prim");
    while (lex_.peek().kind != TokenKind::End) {
        Token t = lex_.peek();
        if (t.isWord("reorder")) {
            unsupported(t, "reorder rootPrims");
        }
        if (!isSpecifier(t)) {
            lex_.unexpected(t, "'def', 'over' or 'class' to start a prim");
        }
        Prim prim = parsePrim(0);
        roots.add(lex_, t, prim.name);
        layer.rootPrims.push_back(std::move(prim));
    }
    return layer;
}

template <class Entry>
void Parser::parseMetadataBlock(Entry&& entry) {
    expect('(', "'('");
    while (!lex_.peek().is(')')) {
        entry();
        separator(')', "a metadata entry");
    }
    lex_.next();
}

void Parser::parseLayerMetadataEntry(Layer& layer, NameScope& seen) {
    const Token& t = lex_.peek();
    if (t.kind == TokenKind::String) {
        parseComment(layer.comment, seen);
    } else if (isListOpKeyword(t)) {
        unsupported(t, std::string(t.text) + " in layer metadata");
    } else if (t.isWord("subLayers")) {
        parseSubLayers(layer, seen);
    } else {
        parseGenericMetadata(layer.metadata, MetadataOwner::Layer, seen);
    }
}

void Parser::parsePrimMetadataEntry(Prim& prim, NameScope& seen) {
    const Token& t = lex_.peek();
    if (t.kind == TokenKind::String) {
        parseComment(prim.comment, seen);
    } else if (isListOpKeyword(t) || t.isWord("apiSchemas") || t.isWord("references")) {
        parseListOpStatement(prim, seen);
    } else if (t.isWord("inherits")) {
        parseInherits(prim, seen);
    } else {
        parseGenericMetadata(prim.metadata, MetadataOwner::Prim, seen);
    }
}

void Parser::parsePropertyMetadataEntry(Dictionary& metadata, std::string& comment, MetadataOwner owner,
                                        NameScope& seen) {
    const Token& t = lex_.peek();
    if (t.kind == TokenKind::String) {
        parseComment(comment, seen);
    } else if (isListOpKeyword(t)) {
        unsupported(t, std::string(t.text) + " in " + std::string(ownerName(owner)) + " metadata");
    } else {
        parseGenericMetadata(metadata, owner, seen);
    }
}

void Parser::parseComment(std::string& comment, NameScope& seen) {
    Token t = lex_.next();
    seen.add(lex_, t, "comment");
    comment = lex_.decodeString(t);
}

void Parser::parseGenericMetadata(Dictionary& metadata, MetadataOwner owner, NameScope& seen) {
    Token key = lex_.next();
    std::string what = std::string(ownerName(owner)) + " metadata";
    if (key.kind != TokenKind::Identifier) {
        lex_.unexpected(key, what + " (a key such as doc) or ')'");
    }
    const MetadataField* field = findMetadataField(key.text, owner);
    if (!field || field->listOp) {
        if (isUnsupportedMetadata(key.text) || key.isWord("inherits") || key.isWord("subLayers")) {
            unsupported(key, key.text);
        }
        lex_.fail(key, "unknown " + what + " '" + std::string(key.text) + "'" + std::string(kSubsetNote));
    }
    seen.add(lex_, key, std::string(key.text));
    expect('=', "'=' after metadata key '" + std::string(key.text) + "'");
    metadata.set(std::string(key.text), values_.parse(field->type));
}

void Parser::parseSubLayers(Layer& layer, NameScope& seen) {
    Token key = lex_.next();
    seen.add(lex_, key, "subLayers");
    expect('=', "'=' after 'subLayers'");
    expect('[', "'[' to start the subLayers list");
    while (!lex_.peek().is(']')) {
        Token t = lex_.next();
        if (t.kind != TokenKind::Asset) {
            lex_.unexpected(t, "a sublayer asset path @...@ or ']'");
        }
        layer.subLayers.push_back(lex_.decodeAsset(t));
        if (lex_.peek().is('(')) {
            unsupported(lex_.peek(), "sublayer offset");
        }
        if (!lex_.peek().is(']')) {
            expect(',', "',' or ']' in the subLayers list");
        }
    }
    lex_.next();
}

// [prepend|append] apiSchemas|references = ...
void Parser::parseListOpStatement(Prim& prim, NameScope& seen) {
    Token first = lex_.next();
    Token key = first;
    std::string op;
    if (isListOpKeyword(first)) {
        op = std::string(first.text);
        key = lex_.next();
        std::string construct = op + (key.kind == TokenKind::Identifier ? " " + std::string(key.text) : "");
        if ((op != "prepend" && op != "append") || !(key.isWord("apiSchemas") || key.isWord("references"))) {
            unsupported(first, construct);
        }
    }
    std::string name(key.text);
    bool explicitSeen = seen.contains(name);
    bool editSeen = seen.contains("prepend " + name) || seen.contains("append " + name);
    if ((op.empty() && editSeen) || (!op.empty() && explicitSeen)) {
        lex_.fail(first, "an explicit '" + name + "' list cannot be combined with prepend/append " + name);
    }
    seen.add(lex_, first, op.empty() ? name : op + " " + name);
    expect('=', "'=' after '" + name + "'");
    auto store = [&](auto& listOp, auto items) {
        auto& target = op.empty() ? listOp.explicitItems : op == "prepend" ? listOp.prepended : listOp.appended;
        target = std::move(items);
        listOp.isExplicit = listOp.isExplicit || op.empty();
    };
    if (name == "apiSchemas") {
        store(prim.apiSchemas, parseTokenList());
    } else {
        store(prim.references, parseReferenceList());
    }
}

void Parser::parseInherits(Prim& prim, NameScope& seen) {
    Token key = lex_.next();
    if (prim.specifier != Specifier::Class) {
        unsupported(key, "inherits");  // accepted only on class prims, as schema files use it
    }
    seen.add(lex_, key, "inherits");
    expect('=', "'=' after 'inherits'");
    prim.inherits = parsePath("inherits", true);
}

std::vector<std::string> Parser::parseTokenList() {
    if (lex_.peek().isWord("None")) {
        lex_.next();
        return {};
    }
    expect('[', "'[' to start a list of quoted names, or None");
    std::vector<std::string> items;
    while (!lex_.peek().is(']')) {
        Token t = lex_.next();
        if (t.kind != TokenKind::String) {
            lex_.unexpected(t, "a quoted name or ']'");
        }
        items.push_back(lex_.decodeString(t));
        if (!lex_.peek().is(']')) {
            expect(',', "',' or ']'");
        }
    }
    lex_.next();
    return items;
}

std::vector<Reference> Parser::parseReferenceList() {
    const Token& t = lex_.peek();
    if (t.isWord("None")) {
        lex_.next();
        return {};
    }
    if (!t.is('[')) {
        return {parseReference()};
    }
    lex_.next();
    std::vector<Reference> items;
    while (!lex_.peek().is(']')) {
        items.push_back(parseReference());
        if (!lex_.peek().is(']')) {
            expect(',', "',' or ']' in the references list");
        }
    }
    lex_.next();
    return items;
}

// @asset@ or @asset@</Prim> or </Prim>
Reference Parser::parseReference() {
    const Token& t = lex_.peek();
    Reference ref;
    ref.location = lex_.where(t);
    if (t.kind == TokenKind::Asset) {
        Token asset = lex_.next();
        ref.assetPath = lex_.decodeAsset(asset);
        if (ref.assetPath.empty() || !isPrintable(ref.assetPath)) {
            lex_.fail(asset, "a reference needs a non-empty asset path without control characters");
        }
        if (lex_.peek().kind == TokenKind::Path) {
            ref.primPath = parsePath("reference", true);
        }
    } else if (t.kind == TokenKind::Path) {
        ref.primPath = parsePath("reference", true);
    } else {
        lex_.unexpected(t, "a reference (@asset@, @asset@</Prim> or </Prim>)");
    }
    if (lex_.peek().is('(')) {
        unsupported(lex_.peek(), "reference layer offset or metadata");
    }
    return ref;
}

Prim Parser::parsePrim(int depth) {
    Token spec = lex_.next();
    if (depth >= kMaxPrimDepth) {
        lex_.fail(spec, "prims nested deeper than " + std::to_string(kMaxPrimDepth) + " levels");
    }
    Prim prim;
    prim.specifier = specifierOf(spec);
    prim.location = lex_.where(spec);
    Token t = lex_.next();
    if (t.kind == TokenKind::Identifier) {
        if (!isIdentifier(t.text)) {
            lex_.fail(t, "invalid prim type name '" + std::string(t.text) + "'");
        }
        prim.typeName = std::string(t.text);
        t = lex_.next();
    }
    if (t.kind != TokenKind::String) {
        lex_.unexpected(t, "a quoted prim name");
    }
    prim.name = lex_.decodeString(t);
    if (!isIdentifier(prim.name)) {
        lex_.fail(t, "prim name '" + prim.name + "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)");
    }
    if (lex_.peek().is('(')) {
        NameScope seen("prim metadata");
        parseMetadataBlock([&] { parsePrimMetadataEntry(prim, seen); });
    }
    expect('{', "'{' to open the body of prim '" + prim.name + "'");
    parsePrimBody(prim, depth);
    return prim;
}

void Parser::parsePrimBody(Prim& prim, int depth) {
    NameScope children("prim"), properties("property"), sampled("timeSamples of property");
    while (true) {
        Token t = lex_.peek();
        if (t.is('}')) {
            lex_.next();
            return;
        }
        if (isSpecifier(t)) {
            Prim child = parsePrim(depth + 1);
            children.add(lex_, t, child.name);
            prim.children.push_back(std::move(child));
            continue;
        }
        rejectBodyKeyword(t);
        addProperty(prim, parseProperty(), t, properties, sampled);
        separator('}', "a property");
    }
}

// An attribute's declaration (with its default) and its `.timeSamples` are two statements
// of one attribute, in either order; each may appear once.
void Parser::addProperty(Prim& prim, Property property, const Token& at, NameScope& declared, NameScope& sampled) {
    auto* added = std::get_if<Attribute>(&property);
    const bool samples = added && !added->timeSamples.empty();
    const std::string name = propertyName(property);
    (samples ? sampled : declared).add(lex_, at, name);
    const auto other = std::find_if(prim.properties.begin(), prim.properties.end(),
                                    [&](const Property& p) { return propertyName(p) == name; });
    if (other == prim.properties.end()) {
        prim.properties.push_back(std::move(property));
        return;
    }
    auto* existing = std::get_if<Attribute>(&*other);
    if (!added || !existing) {
        lex_.fail(at, "'" + name + "' is declared as a relationship and as an attribute (other at " +
                          propertyLocation(*other).str() + ")");
    }
    Attribute& declaration = samples ? *existing : *added;
    if (added->type != existing->type) {
        lex_.fail(at, "the timeSamples of '" + name + "' have type " + typeName(samples ? added->type : existing->type) +
                          " but its declaration has type " + typeName(declaration.type));
    }
    if (declaration.uniform) {
        lex_.fail(at, "'" + name + "' is uniform, so it cannot have timeSamples");
    }
    if (samples) {
        existing->timeSamples = std::move(added->timeSamples);
    } else {
        added->timeSamples = std::move(existing->timeSamples);
        *existing = std::move(*added);
    }
}

void Parser::rejectBodyKeyword(const Token& t) {
    if (t.isWord("variantSet")) {
        unsupported(t, "variantSet");
    }
    if (isListOpKeyword(t)) {
        lex_.next();
        const Token& after = lex_.peek();
        unsupported(t, std::string(t.text) + (after.kind == TokenKind::Identifier ? " " + std::string(after.text) : ""));
    }
    if (t.kind != TokenKind::Identifier) {
        lex_.unexpected(t, "a property, a child prim or '}'");
    }
}

Property Parser::parseProperty() {
    Token first = lex_.peek();
    bool custom = false;
    bool uniform = false;
    if (first.isWord("custom")) {
        custom = true;
        lex_.next();
    }
    Token qualifier = lex_.peek();
    if (qualifier.isWord("uniform") || qualifier.isWord("varying")) {
        uniform = qualifier.isWord("uniform");
        lex_.next();
        if (lex_.peek().isWord("rel")) {
            unsupported(qualifier, std::string(qualifier.text) + " rel");
        }
    }
    if (lex_.peek().isWord("rel")) {
        return parseRelationship(custom, first);
    }
    return parseAttribute(custom, uniform, first);
}

Attribute Parser::parseAttribute(bool custom, bool uniform, const Token& first) {
    Token typeToken = lex_.next();
    if (typeToken.kind != TokenKind::Identifier) {
        lex_.unexpected(typeToken, "an attribute type (e.g. float3, token[]) or 'rel'");
    }
    std::optional<ValueType> type = parseTypeName(typeToken.text);
    if (!type || !isAttributeType(*type)) {
        lex_.fail(typeToken, "unknown or unsupported attribute type '" + std::string(typeToken.text) + "'" +
                                 std::string(kSubsetNote));
    }
    Attribute attr;
    bool sampled = false;
    attr.name = std::string(parsePropertyName("an attribute name", &sampled).text);
    attr.type = *type;
    attr.custom = custom;
    attr.uniform = uniform;
    attr.location = lex_.where(first);
    if (sampled) {
        if (uniform) {
            lex_.fail(first, "'" + attr.name + "' is uniform, so it cannot have timeSamples");
        }
        expect('=', "'=' after " + attr.name + ".timeSamples");
        attr.timeSamples = parseTimeSamples(*type);
        if (lex_.peek().is('(')) {
            lex_.fail(lex_.peek(), "metadata belongs on the attribute's declaration, not on its timeSamples");
        }
        return attr;
    }
    if (lex_.peek().is('=')) {
        lex_.next();
        attr.value = values_.parse(*type, true);
    }
    if (lex_.peek().is('(')) {
        NameScope seen("attribute metadata");
        parseMetadataBlock(
            [&] { parsePropertyMetadataEntry(attr.metadata, attr.comment, MetadataOwner::Attribute, seen); });
    }
    return attr;
}

Relationship Parser::parseRelationship(bool custom, const Token& first) {
    lex_.next();  // rel
    Relationship rel;
    rel.name = std::string(parsePropertyName("a relationship name").text);
    rel.custom = custom;
    rel.location = lex_.where(first);
    if (lex_.peek().is('=')) {
        lex_.next();
        rel.targets = parseTargets();
    }
    if (lex_.peek().is('(')) {
        NameScope seen("relationship metadata");
        parseMetadataBlock(
            [&] { parsePropertyMetadataEntry(rel.metadata, rel.comment, MetadataOwner::Relationship, seen); });
    }
    return rel;
}

// A property name; `.timeSamples` sets *timeSamples where allowed (attributes), other
// suffixes (`.connect`, `.spline`, `.default`) are rejected.
Token Parser::parsePropertyName(std::string_view what, bool* timeSamples) {
    Token name = lex_.next();
    if (name.kind != TokenKind::Identifier || !isNamespacedName(name.text)) {
        lex_.unexpected(name, what);
    }
    if (lex_.peek().is('.')) {
        lex_.next();
        Token suffix = lex_.next();
        if (timeSamples && suffix.isWord("timeSamples")) {
            *timeSamples = true;
            return name;
        }
        if (suffix.kind == TokenKind::Identifier) {
            unsupported(suffix, suffix.text);
        }
        lex_.unexpected(suffix, "a property name suffix");
    }
    return name;
}

// `{ time: value, ... }`: time codes are numbers, each at most once; values of the
// attribute's type or None. Kept sorted by time, as Sdf keeps them.
std::vector<TimeSample> Parser::parseTimeSamples(ValueType type) {
    const Token open = expect('{', "'{' to open the time samples");
    std::vector<TimeSample> samples;
    std::map<double, SourceLocation> seen;
    while (!lex_.peek().is('}')) {
        const Token at = lex_.peek();
        if (at.kind != TokenKind::Number) {
            lex_.unexpected(at, "a time code (a number) or '}'");
        }
        const double time = values_.parse(types::Double).get<types::Double>("time code");
        if (const auto [it, inserted] = seen.emplace(time, lex_.where(at)); !inserted) {
            lex_.fail(at, "duplicate time sample " + std::string(at.text) + " (first at " + it->second.str() + ")");
        }
        expect(':', "':' after the time code");
        samples.push_back({time, values_.parse(type, true)});
        if (!lex_.peek().is('}')) {
            expect(',', "',' or '}' after a time sample");
        }
    }
    lex_.next();
    if (samples.empty()) {
        lex_.fail(open, "timeSamples = {} holds no sample (remove it, or author a default value)");
    }
    std::stable_sort(samples.begin(), samples.end(),
                     [](const TimeSample& a, const TimeSample& b) { return a.time < b.time; });
    return samples;
}

std::vector<std::string> Parser::parseTargets() {
    const Token& t = lex_.peek();
    if (t.isWord("None")) {
        lex_.next();
        return {};
    }
    if (t.kind == TokenKind::Path) {
        return {parsePath("relationship target", false)};
    }
    if (!t.is('[')) {
        lex_.unexpected(t, "a target path <...>, a list of them [...] or None");
    }
    lex_.next();
    std::vector<std::string> targets;
    while (!lex_.peek().is(']')) {
        targets.push_back(parsePath("relationship target", false));
        if (!lex_.peek().is(']')) {
            expect(',', "',' or ']' in the target list");
        }
    }
    lex_.next();
    return targets;
}

std::string Parser::parsePath(std::string_view what, bool primOnly) {
    Token t = lex_.next();
    if (t.kind != TokenKind::Path) {
        lex_.unexpected(t, "a path <...> for " + std::string(what));
    }
    std::string_view path = lex_.pathText(t);
    bool valid = isPath(path) && (!primOnly || (path.starts_with('/') && path.find('.') == std::string_view::npos));
    if (!valid) {
        lex_.fail(t, "invalid " + std::string(what) + " path <" + std::string(path) + ">" +
                         (primOnly ? " (expected an absolute prim path such as </Root/Child>)" : ""));
    }
    return std::string(path);
}

Token Parser::expect(char punct, std::string_view expected) {
    Token t = lex_.next();
    if (!t.is(punct)) {
        lex_.unexpected(t, expected);
    }
    return t;
}

void Parser::separator(char closing, std::string_view after) {
    const Token& t = lex_.peek();
    if (t.is(';')) {
        lex_.next();
    } else if (!t.is(closing) && !t.newlineBefore) {
        lex_.unexpected(t, "a newline or ';' after " + std::string(after));
    }
}

void Parser::unsupported(const Token& at, std::string_view construct) {
    lex_.fail(at, "unsupported construct '" + std::string(construct) + "'" + std::string(kSubsetNote));
}

}  // namespace

Layer readUsda(std::string_view text, std::string_view sourceName) {
    Parser parser(text, std::make_shared<const std::string>(sourceName));
    return parser.parseLayer();
}

Layer readUsdaFile(const std::filesystem::path& path) {
    std::error_code ec;
    std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        throw opal::Error(path.string() + ": cannot read USDA layer: " + ec.message());
    }
    if (size > kMaxUsdaFileBytes) {
        throw opal::Error(path.string() + ": USDA layer of " + std::to_string(size) + " bytes exceeds the " +
                          std::to_string(kMaxUsdaFileBytes) + "-byte limit");
    }
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(text.data(), static_cast<std::streamsize>(size))) {
        throw opal::Error(path.string() + ": cannot read USDA layer");
    }
    return readUsda(text, path.string());
}

}  // namespace opal::usda
