#include "bake/ply_header.h"

#include "schema/error.h"

#include <array>
#include <charconv>
#include <sstream>
#include <utility>

namespace opal {
namespace {

// PLY's type names, both the original and the sized spellings.
constexpr std::array<std::pair<std::string_view, PlyScalar>, 16> kTypeNames = {{
    {"char", PlyScalar::Int8},     {"int8", PlyScalar::Int8},      {"uchar", PlyScalar::UInt8},
    {"uint8", PlyScalar::UInt8},   {"short", PlyScalar::Int16},    {"int16", PlyScalar::Int16},
    {"ushort", PlyScalar::UInt16}, {"uint16", PlyScalar::UInt16},  {"int", PlyScalar::Int32},
    {"int32", PlyScalar::Int32},   {"uint", PlyScalar::UInt32},    {"uint32", PlyScalar::UInt32},
    {"float", PlyScalar::Float32}, {"float32", PlyScalar::Float32}, {"double", PlyScalar::Float64},
    {"float64", PlyScalar::Float64},
}};

class HeaderParser {
public:
    HeaderParser(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

    PlyHeader parse() {
        if (nextLine() != "ply") fail("not a PLY file (the first line is not 'ply')");
        PlyHeader header;
        bool sawFormat = false;
        for (;;) {
            if (pos_ >= bytes_.size()) fail("the header has no 'end_header' line");
            const std::string_view line = nextLine();
            std::istringstream words{std::string(line)};
            std::string keyword;
            words >> keyword;
            if (keyword == "end_header") break;
            if (keyword == "format") {
                header.format = format(words);
                sawFormat = true;
            } else if (keyword == "element") {
                header.elements.push_back(element(words));
            } else if (keyword == "property") {
                if (header.elements.empty()) fail("a property before any element");
                header.elements.back().properties.push_back(property(words));
            } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
                fail("unknown header keyword '" + keyword + "'");
            }
        }
        if (!sawFormat) fail("the header has no 'format' line");
        header.dataOffset = pos_;
        return header;
    }

private:
    // The next line without its line end ("\n" or "\r\n").
    std::string_view nextLine() {
        ++line_;
        const std::size_t end = bytes_.find('\n', pos_);
        std::string_view text = bytes_.substr(pos_, end == std::string_view::npos ? std::string_view::npos : end - pos_);
        pos_ = end == std::string_view::npos ? bytes_.size() : end + 1;
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        return text;
    }

    [[noreturn]] void fail(const std::string& problem) const {
        throw Error(file_ + ":" + std::to_string(line_) + ": " + problem);
    }

    PlyFormat format(std::istringstream& words) {
        std::string name;
        words >> name;
        if (name == "ascii") return PlyFormat::Ascii;
        if (name == "binary_little_endian") return PlyFormat::BinaryLittleEndian;
        if (name == "binary_big_endian") return PlyFormat::BinaryBigEndian;
        fail("unknown format '" + name + "' (ascii, binary_little_endian or binary_big_endian)");
    }

    PlyElement element(std::istringstream& words) {
        PlyElement e;
        std::string count;
        words >> e.name >> count;
        const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), e.count);
        if (e.name.empty() || ec != std::errc() || end != count.data() + count.size())
            fail("expected 'element NAME COUNT'");
        return e;
    }

    PlyScalar scalar(const std::string& name) {
        for (const auto& [spelling, type] : kTypeNames)
            if (spelling == name) return type;
        fail("unknown property type '" + name + "'");
    }

    PlyProperty property(std::istringstream& words) {
        PlyProperty p;
        std::string first;
        words >> first;
        if (first == "list") {
            std::string countType, itemType;
            words >> countType >> itemType >> p.name;
            p.isList = true;
            p.countType = scalar(countType);
            p.type = scalar(itemType);
            if (!plyScalarIsInteger(p.countType)) fail("a list's length type must be an integer type");
        } else {
            p.type = scalar(first);
            words >> p.name;
        }
        if (p.name.empty()) fail("a property without a name");
        return p;
    }

    std::string_view bytes_;
    const std::string& file_;
    std::size_t pos_ = 0;
    std::size_t line_ = 0;
};

}  // namespace

std::size_t plyScalarSize(PlyScalar type) {
    switch (type) {
        case PlyScalar::Int8:
        case PlyScalar::UInt8: return 1;
        case PlyScalar::Int16:
        case PlyScalar::UInt16: return 2;
        case PlyScalar::Int32:
        case PlyScalar::UInt32:
        case PlyScalar::Float32: return 4;
        case PlyScalar::Float64: return 8;
    }
    return 0;
}

bool plyScalarIsInteger(PlyScalar type) { return type != PlyScalar::Float32 && type != PlyScalar::Float64; }

const PlyElement* PlyHeader::find(std::string_view name) const {
    for (const PlyElement& e : elements)
        if (e.name == name) return &e;
    return nullptr;
}

PlyHeader parsePlyHeader(std::string_view bytes, const std::string& file) { return HeaderParser(bytes, file).parse(); }

}  // namespace opal
