#include "schema/usd/usda_value_writer.h"

#include "schema/error.h"
#include "schema/usd/usda_syntax.h"
#include "schema/usd/utf8.h"

#include <cmath>
#include <type_traits>

namespace opal::usda {
namespace {

class ValueFormatter {
public:
    ValueFormatter(std::string& out, ValueType type, BoolStyle style, std::string_view context)
        : out_(out), type_(type), style_(style), context_(context) {}

    void value(const Value::Data& data, int indent) {
        std::visit([&](const auto& v) { element(v, indent); }, data);
    }

private:
    void element(std::monostate, int) { out_ += "None"; }
    void element(bool v, int) { out_ += style_ == BoolStyle::Words ? (v ? "true" : "false") : (v ? "1" : "0"); }

    template <class T>
        requires std::is_integral_v<T>
    void element(T v, int) {
        if constexpr (std::is_signed_v<T>) {
            appendNumber(out_, static_cast<std::int64_t>(v));
        } else {
            appendNumber(out_, static_cast<std::uint64_t>(v));
        }
    }

    template <class T>
        requires std::is_floating_point_v<T>
    void element(T v, int) {
        if (!std::isfinite(v)) {
            throw opal::Error("cannot write " + std::string(context_) + ": non-finite number (USDA as Opal writes it carries finite numbers only)");
        }
        appendNumber(out_, v);
    }

    void element(const std::string& s, int) {
        // The reader refuses such text, so writing it would make a layer Opal cannot read back.
        if (std::size_t bad = firstBadTextByte(s); bad != std::string::npos) {
            throw opal::Error("cannot write " + std::string(context_) + ": text holds " +
                              (s[bad] == '\0' ? "a NUL byte" : "bytes that are not valid UTF-8") + " at byte " +
                              std::to_string(bad));
        }
        if (type_.scalar != ScalarType::Asset) {
            out_ += quoteString(s);
            return;
        }
        if (!isPrintable(s)) {
            throw opal::Error("cannot write " + std::string(context_) + ": asset path contains a control character");
        }
        out_ += quoteAssetPath(s);
    }

    template <class E, std::size_t N>
    void element(const std::array<E, N>& tuple, int indent) {
        constexpr bool isMatrix = !std::is_arithmetic_v<E>;
        out_ += isMatrix ? "( " : "(";
        for (std::size_t i = 0; i < N; ++i) {
            out_ += i > 0 ? ", " : "";
            element(tuple[i], indent);
        }
        out_ += isMatrix ? " )" : ")";
    }

    template <class E>
    void element(const std::vector<E>& array, int indent) {
        out_ += '[';
        for (std::size_t i = 0; i < array.size(); ++i) {
            if (i > 0) {
                out_ += ", ";
            }
            if constexpr (std::is_same_v<E, bool>) {
                element(static_cast<bool>(array[i]), indent);
            } else {
                element(array[i], indent);
            }
        }
        out_ += ']';
    }

    void element(const Dictionary& dict, int indent) {
        out_ += "{\n";
        for (const DictionaryEntry& entry : dict.entries()) {
            appendIndent(out_, indent + 1);
            out_ += typeName(entry.value.type());
            out_ += ' ';
            out_ += isIdentifier(entry.key) ? entry.key : quoteString(entry.key);
            out_ += " = ";
            if (entry.value.isNone()) {
                throw opal::Error("cannot write " + std::string(context_) + ": dictionary entry '" + entry.key + "' is None");
            }
            std::string inner = std::string(context_) + " entry '" + entry.key + "'";
            appendValue(out_, entry.value, indent + 1, BoolStyle::Digits, inner);
            out_ += '\n';
        }
        appendIndent(out_, indent);
        out_ += '}';
    }

    std::string& out_;
    ValueType type_;
    BoolStyle style_;
    std::string_view context_;
};

}  // namespace

void appendIndent(std::string& out, int indent) { out.append(static_cast<std::size_t>(indent) * 4, ' '); }

void appendValue(std::string& out, const Value& value, int indent, BoolStyle style, std::string_view context) {
    ValueFormatter(out, value.type(), style, context).value(value.data(), indent);
}

}  // namespace opal::usda
