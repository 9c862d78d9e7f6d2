#include "schema/usd/usda_writer.h"

#include "schema/error.h"
#include "schema/usd/atomic_file.h"
#include "schema/usd/usda_metadata.h"
#include "schema/usd/usda_syntax.h"
#include "schema/usd/usda_value_writer.h"

#include <algorithm>
#include <unordered_set>

namespace opal::usda {
namespace {

// One metadata statement, already formatted (indentation and newline included), and
// the Sdf field name it sorts by.
struct MetadataLine {
    std::string sortKey;
    std::string text;
};

class Writer {
public:
    std::string write(const Layer& layer);

private:
    void layerHeader(const Layer& layer);
    void prim(const Prim& prim, int indent, const std::string& parentPath);
    void primHeader(const Prim& prim, int indent, const std::string& path);
    void property(const Property& property, int indent, const std::string& primPath);
    void attribute(const Attribute& attr, int indent, const std::string& path);
    void declaration(const Attribute& attr, int indent);
    void timeSamples(const Attribute& attr, int indent, const std::string& path);
    void relationship(const Relationship& rel, int indent, const std::string& path);
    void metadataBlock(const std::string& comment, std::vector<MetadataLine> lines, int indent);
    void metadataLines(std::vector<MetadataLine>& lines, const Dictionary& metadata, MetadataOwner owner,
                       int indent, const std::string& context);
    void listOpLines(std::vector<MetadataLine>& lines, const ListOp<std::string>& op, int indent,
                     const std::string& context);
    void listOpLines(std::vector<MetadataLine>& lines, const ListOp<Reference>& op, int indent,
                     const std::string& context);
    template <class T, class Format>
    void listOpLinesOf(std::vector<MetadataLine>& lines, const ListOp<T>& op, std::string_view name, int indent,
                       Format&& format);

    std::string out_;
};

[[noreturn]] void fail(const std::string& context, const std::string& what) {
    throw opal::Error("cannot write USDA: " + context + ": " + what);
}

std::string quotedNameList(const std::vector<std::string>& names) {
    std::string out = "[";
    for (std::size_t i = 0; i < names.size(); ++i) {
        out += (i > 0 ? ", " : "") + quoteString(names[i]);
    }
    return out + "]";
}

std::string referenceText(const Reference& ref, const std::string& context) {
    bool primPathOk = ref.primPath.empty()
                          ? !ref.assetPath.empty()
                          : isPath(ref.primPath) && ref.primPath.starts_with('/') &&
                                ref.primPath.find('.') == std::string::npos;
    if (!primPathOk || !isPrintable(ref.assetPath)) {
        fail(context, "invalid reference @" + ref.assetPath + "@<" + ref.primPath + ">");
    }
    std::string text = ref.assetPath.empty() ? std::string() : quoteAssetPath(ref.assetPath);
    return ref.primPath.empty() ? text : text + "<" + ref.primPath + ">";
}

std::string pathText(const std::string& path, const std::string& context) {
    if (!isPath(path)) {
        fail(context, "invalid path <" + path + ">");
    }
    return "<" + path + ">";
}

std::string Writer::write(const Layer& layer) {
    layerHeader(layer);
    std::unordered_set<std::string_view> names;
    for (const Prim& root : layer.rootPrims) {
        if (!names.insert(root.name).second) {
            fail("/" + root.name, "duplicate root prim name");
        }
        out_ += '\n';
        prim(root, 0, "");
    }
    return std::move(out_);
}

void Writer::layerHeader(const Layer& layer) {
    out_ += "#usda 1.0\n";
    std::vector<MetadataLine> lines;
    metadataLines(lines, layer.metadata, MetadataOwner::Layer, 1, "layer metadata");
    if (!layer.subLayers.empty()) {
        std::string text = "    subLayers = [\n";
        for (std::size_t i = 0; i < layer.subLayers.size(); ++i) {
            if (!isPrintable(layer.subLayers[i])) {
                fail("layer subLayers", "asset path contains a control character");
            }
            text += "        " + quoteAssetPath(layer.subLayers[i]) + (i + 1 < layer.subLayers.size() ? ",\n" : "\n");
        }
        lines.push_back({"subLayers", text + "    ]\n"});
    }
    if (layer.comment.empty() && lines.empty()) {
        return;
    }
    out_ += '(';
    metadataBlock(layer.comment, std::move(lines), 0);
    out_ += '\n';
}

void Writer::prim(const Prim& prim, int indent, const std::string& parentPath) {
    std::string path = parentPath + "/" + prim.name;
    primHeader(prim, indent, path);
    out_ += '\n';
    appendIndent(out_, indent);
    out_ += "{\n";
    std::unordered_set<std::string_view> names;
    for (const Property& p : prim.properties) {
        if (!names.insert(propertyName(p)).second) {
            fail(path + "." + propertyName(p), "duplicate property name");
        }
        property(p, indent + 1, path);
    }
    names.clear();
    for (std::size_t i = 0; i < prim.children.size(); ++i) {
        const Prim& child = prim.children[i];
        if (!names.insert(child.name).second) {
            fail(path + "/" + child.name, "duplicate prim name");
        }
        if (i > 0 || !prim.properties.empty()) {
            out_ += '\n';
        }
        this->prim(child, indent + 1, path);
    }
    appendIndent(out_, indent);
    out_ += "}\n";
}

void Writer::primHeader(const Prim& prim, int indent, const std::string& path) {
    if (!isIdentifier(prim.name)) {
        fail(path, "prim name is not an identifier");
    }
    if (!prim.typeName.empty() && !isIdentifier(prim.typeName)) {
        fail(path, "prim type name '" + prim.typeName + "' is not an identifier");
    }
    appendIndent(out_, indent);
    out_ += specifierKeyword(prim.specifier);
    if (!prim.typeName.empty()) {
        out_ += ' ';
        out_ += prim.typeName;
    }
    out_ += ' ';
    out_ += quoteString(prim.name);

    std::vector<MetadataLine> lines;
    metadataLines(lines, prim.metadata, MetadataOwner::Prim, indent + 1, path);
    listOpLines(lines, prim.apiSchemas, indent + 1, path);
    listOpLines(lines, prim.references, indent + 1, path);
    if (prim.inherits) {
        if (prim.specifier != Specifier::Class) {
            fail(path, "inherits is written only on class prims");
        }
        std::string text(static_cast<std::size_t>(indent + 1) * 4, ' ');
        text += "inherits = " + pathText(*prim.inherits, path) + "\n";
        lines.push_back({"inheritPaths", text});
    }
    if (!prim.comment.empty() || !lines.empty()) {
        out_ += " (";
        metadataBlock(prim.comment, std::move(lines), indent);
    }
}

void Writer::property(const Property& p, int indent, const std::string& primPath) {
    std::string path = primPath + "." + propertyName(p);
    if (!isNamespacedName(propertyName(p))) {
        fail(path, "property name is not a (namespaced) identifier");
    }
    if (const auto* attr = std::get_if<Attribute>(&p)) {
        attribute(*attr, indent, path);
    } else {
        relationship(std::get<Relationship>(p), indent, path);
    }
}

// The declaration (default and metadata) and, when the attribute is animated, a second
// statement with its timeSamples, as Sdf writes them.
void Writer::attribute(const Attribute& attr, int indent, const std::string& path) {
    const auto mismatched = [&](const Value& v) { return v.type() != attr.type; };
    if (!isAttributeType(attr.type) || (attr.value && mismatched(*attr.value))) {
        fail(path, "attribute type " + typeName(attr.type) + " does not match its value" +
                       (attr.value ? " of type " + typeName(attr.value->type()) : ""));
    }
    std::vector<MetadataLine> lines;
    metadataLines(lines, attr.metadata, MetadataOwner::Attribute, indent + 1, path);
    const bool declared = attr.value || !attr.comment.empty() || !lines.empty() || attr.timeSamples.empty();
    if (declared) {
        declaration(attr, indent);
        if (attr.value) {
            out_ += " = ";
            appendValue(out_, *attr.value, indent, BoolStyle::Digits, "attribute " + path);
        }
        if (!attr.comment.empty() || !lines.empty()) {
            out_ += " (";
            metadataBlock(attr.comment, std::move(lines), indent);
        }
        out_ += '\n';
    }
    if (!attr.timeSamples.empty()) timeSamples(attr, indent, path);
}

void Writer::declaration(const Attribute& attr, int indent) {
    appendIndent(out_, indent);
    out_ += attr.custom ? "custom " : "";
    out_ += attr.uniform ? "uniform " : "";
    out_ += typeName(attr.type) + " " + attr.name;
}

void Writer::timeSamples(const Attribute& attr, int indent, const std::string& path) {
    if (attr.uniform) fail(path, "a uniform attribute cannot have timeSamples");
    declaration(attr, indent);
    out_ += ".timeSamples = {\n";
    for (std::size_t i = 0; i < attr.timeSamples.size(); ++i) {
        const TimeSample& sample = attr.timeSamples[i];
        if (sample.value.type() != attr.type)
            fail(path, "time sample at " + std::to_string(sample.time) + " has type " + typeName(sample.value.type()) +
                           ", the attribute " + typeName(attr.type));
        if (i > 0 && !(attr.timeSamples[i - 1].time < sample.time))
            fail(path, "time samples are not in increasing order of time");
        appendIndent(out_, indent + 1);
        appendValue(out_, Value::make<types::Double>(sample.time), indent + 1, BoolStyle::Digits,
                    "time code of " + path);
        out_ += ": ";
        appendValue(out_, sample.value, indent + 1, BoolStyle::Digits, "attribute " + path);
        out_ += ",\n";
    }
    appendIndent(out_, indent);
    out_ += "}\n";
}

void Writer::relationship(const Relationship& rel, int indent, const std::string& path) {
    appendIndent(out_, indent);
    out_ += rel.custom ? "custom rel " : "rel ";
    out_ += rel.name;
    if (rel.targets && rel.targets->empty()) {
        out_ += " = None";
    } else if (rel.targets && rel.targets->size() == 1) {
        out_ += " = " + pathText(rel.targets->front(), path);
    } else if (rel.targets) {
        out_ += " = [\n";
        for (const std::string& target : *rel.targets) {
            appendIndent(out_, indent + 1);
            out_ += pathText(target, path) + ",\n";
        }
        appendIndent(out_, indent);
        out_ += ']';
    }
    std::vector<MetadataLine> lines;
    metadataLines(lines, rel.metadata, MetadataOwner::Relationship, indent + 1, path);
    if (!rel.comment.empty() || !lines.empty()) {
        out_ += " (";
        metadataBlock(rel.comment, std::move(lines), indent);
    }
    out_ += '\n';
}

// "\n" comment, lines sorted by Sdf field name, ")" at `indent`; the caller wrote "(".
void Writer::metadataBlock(const std::string& comment, std::vector<MetadataLine> lines, int indent) {
    out_ += '\n';
    if (!comment.empty()) {
        appendIndent(out_, indent + 1);
        out_ += quoteString(comment) + "\n";
    }
    std::stable_sort(lines.begin(), lines.end(), [](const MetadataLine& a, const MetadataLine& b) {
        return dictionaryLess(a.sortKey, b.sortKey);
    });
    for (const MetadataLine& line : lines) {
        out_ += line.text;
    }
    appendIndent(out_, indent);
    out_ += ')';
}

void Writer::metadataLines(std::vector<MetadataLine>& lines, const Dictionary& metadata, MetadataOwner owner,
                           int indent, const std::string& context) {
    for (const DictionaryEntry& entry : metadata.entries()) {
        const MetadataField* field = findMetadataField(entry.key, owner);
        if (!field || field->listOp) {
            fail(context, "'" + entry.key + "' is not " + std::string(ownerName(owner)) +
                              " metadata in Opal's USDA subset");
        }
        if (entry.value.type() != field->type || entry.value.isNone()) {
            fail(context, "metadata '" + entry.key + "' must have type " + typeName(field->type));
        }
        std::string text(static_cast<std::size_t>(indent) * 4, ' ');
        text += entry.key + " = ";
        appendValue(text, entry.value, indent, BoolStyle::Words, context + " metadata '" + entry.key + "'");
        lines.push_back({std::string(field->sortKey), text + "\n"});
    }
}

template <class T, class Format>
void Writer::listOpLinesOf(std::vector<MetadataLine>& lines, const ListOp<T>& op, std::string_view name,
                           int indent, Format&& format) {
    auto add = [&](std::string_view keyword, const std::vector<T>& items) {
        std::string text(static_cast<std::size_t>(indent) * 4, ' ');
        text += keyword.empty() ? "" : std::string(keyword) + " ";
        text += std::string(name) + " = " + (items.empty() ? std::string("None") : format(items)) + "\n";
        lines.push_back({std::string(name), text});
    };
    if (op.isExplicit) {
        if (!op.prepended.empty() || !op.appended.empty()) {
            fail(std::string(name), "an explicit list cannot also prepend or append");
        }
        add("", op.explicitItems);
        return;
    }
    if (!op.prepended.empty()) {
        add("prepend", op.prepended);
    }
    if (!op.appended.empty()) {
        add("append", op.appended);
    }
}

void Writer::listOpLines(std::vector<MetadataLine>& lines, const ListOp<std::string>& op, int indent,
                         const std::string&) {
    listOpLinesOf(lines, op, "apiSchemas", indent, quotedNameList);
}

void Writer::listOpLines(std::vector<MetadataLine>& lines, const ListOp<Reference>& op, int indent,
                         const std::string& context) {
    listOpLinesOf(lines, op, "references", indent, [&](const std::vector<Reference>& refs) {
        if (refs.size() == 1) {
            return referenceText(refs.front(), context);
        }
        std::string text = "[\n";
        for (std::size_t i = 0; i < refs.size(); ++i) {
            text += std::string(static_cast<std::size_t>(indent + 1) * 4, ' ') + referenceText(refs[i], context);
            text += i + 1 < refs.size() ? ",\n" : "\n";
        }
        return text + std::string(static_cast<std::size_t>(indent) * 4, ' ') + "]";
    });
}

}  // namespace

std::string writeUsda(const Layer& layer) { return Writer().write(layer); }

void writeUsdaFile(const std::filesystem::path& path, const Layer& layer) {
    std::string text;
    try {
        text = writeUsda(layer);
    } catch (const opal::Error& e) {
        throw opal::Error(path.string() + ": " + e.what());
    }
    writeFileAtomically(path, text);
}

}  // namespace opal::usda
