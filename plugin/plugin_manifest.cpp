#include "plugin/plugin_manifest.h"

#include "schema/error.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

namespace opal {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string readText(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw Error(file.string() + ": no such plugin manifest");
    if (fs::is_directory(file, ec)) throw Error(file.string() + ": is a directory, not a plugin manifest");
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    if (!(in && text << in.rdbuf())) throw Error(file.string() + ": cannot read plugin manifest");
    return text.str();
}

// USD's rule: a line whose first character other than blanks is '#' is a comment. It is
// blanked rather than removed so that JSON errors report the file's own line numbers.
std::string blankCommentLines(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        if (line.find('#') >= line.find_first_not_of(" \t#")) out += line;
        if (end == text.size()) break;
        out += '\n';
        start = end + 1;
    }
    return out;
}

struct LineColumn {
    std::size_t line = 1, column = 1;
};

// nlohmann reports the 1-based count of bytes read when the error was found; the
// offending character is the last one read.
LineColumn lineColumnOf(std::string_view text, std::size_t bytesRead) {
    std::size_t offset = std::min(bytesRead > 0 ? bytesRead - 1 : 0, text.size());
    LineColumn at;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else {
            ++at.column;
        }
    }
    return at;
}

// nlohmann's message without its "[json.exception...] parse error at line L, column C: "
// prefix (the location is reported in the file:line:column form instead).
std::string parseErrorReason(const std::string& what) {
    std::size_t column = what.find("column ");
    std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

json parseJson(const std::string& text, const fs::path& file) {
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        LineColumn at = lineColumnOf(text, e.byte);
        throw Error(file.string() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                    ": JSON syntax error: " + parseErrorReason(e.what()));
    }
}

bool isRelative(const std::string& path) { return !path.empty() && path.front() != '/'; }

// Without "." and ".." components or a trailing separator.
fs::path normalized(const fs::path& path) {
    fs::path normal = path.lexically_normal();
    return normal.has_filename() || normal == normal.root_path() ? normal : normal.parent_path();
}

// `relative` joined to `base` unless it is absolute (USD's _MergePaths/_AppendToRootPath).
fs::path resolve(const fs::path& base, const std::string& relative) {
    return normalized(isRelative(relative) ? base / relative : fs::path(relative));
}

// Reads one manifest's JSON tree into a PluginManifest, naming the file and the JSON
// location of every problem.
class ManifestParser {
public:
    explicit ManifestParser(PluginManifest& manifest) : m_(manifest) {}

    void parseTop(const json& top) {
        if (!top.is_object()) fail("top level", "expected a JSON object, found " + std::string(top.type_name()));
        warnUnknownKeys(top, "top level", {"Plugins", "Includes"});
        if (auto it = top.find("Plugins"); it != top.end()) parsePlugins(*it);
        if (auto it = top.find("Includes"); it != top.end()) parseIncludes(*it);
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
        throw Error(m_.path.string() + ": " + where + ": " + problem);
    }

    void expectType(const json& value, json::value_t type, const std::string& where) const {
        if (value.type() == type) return;
        const char* expected = type == json::value_t::object  ? "an object"
                               : type == json::value_t::array ? "an array"
                                                              : "a string";
        fail(where, std::string("expected ") + expected + ", found " + value.type_name());
    }

    void warnUnknownKeys(const json& object, const std::string& where, std::initializer_list<std::string_view> known) {
        for (const auto& [key, value] : object.items())
            if (std::find(known.begin(), known.end(), key) == known.end())
                m_.warnings.push_back(m_.path.string() + ": " + where + ": unknown key '" + key + "' ignored");
    }

    std::optional<std::string> optionalString(const json& object, const char* key, const std::string& where) const {
        auto it = object.find(key);
        if (it == object.end()) return std::nullopt;
        expectType(*it, json::value_t::string, where + "." + key);
        return it->get<std::string>();
    }

    std::string requiredString(const json& object, const char* key, const std::string& where) const {
        std::optional<std::string> value = optionalString(object, key, where);
        if (!value) fail(where, "required key '" + std::string(key) + "' is missing");
        return *value;
    }

    void parseIncludes(const json& includes) {
        expectType(includes, json::value_t::array, "Includes");
        const std::string dir = m_.path.parent_path().string();
        for (std::size_t i = 0; i < includes.size(); ++i) {
            std::string where = "Includes[" + std::to_string(i) + "]";
            expectType(includes[i], json::value_t::string, where);
            std::string include = includes[i].get<std::string>();
            if (include.empty()) fail(where, "empty path");
            m_.includes.push_back(isRelative(include) ? dir + "/" + include : include);
        }
    }

    void parsePlugins(const json& plugins) {
        expectType(plugins, json::value_t::array, "Plugins");
        for (std::size_t i = 0; i < plugins.size(); ++i)
            m_.plugins.push_back(parsePlugin(plugins[i], "Plugins[" + std::to_string(i) + "]"));
    }

    PluginEntry::Kind parseKind(const json& plugin, const std::string& where) const {
        std::string type = requiredString(plugin, "Type", where);
        if (type == "library") return PluginEntry::Kind::Library;
        if (type == "resource") return PluginEntry::Kind::Resource;
        if (type == "python") fail(where + ".Type", "python plugins are not supported by Opal");
        fail(where + ".Type", "'" + type + "' is not a plugin type (expected \"library\" or \"resource\")");
    }

    PluginEntry parsePlugin(const json& plugin, const std::string& where) {
        expectType(plugin, json::value_t::object, where);
        warnUnknownKeys(plugin, where, {"Type", "Name", "Info", "Root", "LibraryPath", "ResourcePath"});
        PluginEntry entry;
        entry.location = where;
        entry.kind = parseKind(plugin, where);
        entry.name = requiredString(plugin, "Name", where);
        if (entry.name.empty()) fail(where + ".Name", "empty plugin name");
        parsePaths(plugin, where, entry);
        auto info = plugin.find("Info");
        if (info == plugin.end()) fail(where, "required key 'Info' is missing");
        expectType(*info, json::value_t::object, where + ".Info");
        entry.info = *info;
        entry.types = parseTypes(*info, where + ".Info");
        return entry;
    }

    // Root is relative to the manifest's directory, LibraryPath and ResourcePath to Root.
    void parsePaths(const json& plugin, const std::string& where, PluginEntry& entry) const {
        entry.root = m_.path.parent_path();
        if (auto root = optionalString(plugin, "Root", where)) {
            if (root->empty()) fail(where + ".Root", "empty path");
            entry.root = resolve(entry.root, *root);
        }
        std::optional<std::string> library = optionalString(plugin, "LibraryPath", where);
        if (!library && entry.kind == PluginEntry::Kind::Library)
            fail(where, "required key 'LibraryPath' is missing (a \"library\" plugin names its library)");
        if (library && !library->empty()) entry.libraryPath = resolve(entry.root, *library);
        std::optional<std::string> resources = optionalString(plugin, "ResourcePath", where);
        entry.resourcePath = resources && !resources->empty() ? resolve(entry.root, *resources) : entry.root;
    }

    std::vector<PluginType> parseTypes(const json& info, const std::string& where) const {
        std::vector<PluginType> types;
        auto found = info.find("Types");
        if (found == info.end()) return types;
        expectType(*found, json::value_t::object, where + ".Types");
        for (const auto& [name, entry] : found->items()) {
            PluginType type{name, {}, entry, where + ".Types." + name};
            expectType(entry, json::value_t::object, type.location);
            type.bases = parseBases(entry, type.location);
            types.push_back(std::move(type));
        }
        return types;
    }

    std::vector<std::string> parseBases(const json& type, const std::string& where) const {
        std::vector<std::string> bases;
        auto found = type.find("bases");
        if (found == type.end()) return bases;
        expectType(*found, json::value_t::array, where + ".bases");
        for (std::size_t i = 0; i < found->size(); ++i) {
            expectType((*found)[i], json::value_t::string, where + ".bases[" + std::to_string(i) + "]");
            bases.push_back((*found)[i].get<std::string>());
        }
        return bases;
    }

    PluginManifest& m_;
};

// '*' matches any run of characters; everything else is literal (USD's wildcards). As
// glob(3), a leading '.' is only matched by a pattern that starts with one.
bool wildcardMatch(std::string_view pattern, std::string_view name) {
    if (!name.empty() && name.front() == '.' && (pattern.empty() || pattern.front() != '.')) return false;
    std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
    while (n < name.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = n;
        } else if (p < pattern.size() && pattern[p] == name[n]) {
            ++p;
            ++n;
        } else if (star != std::string_view::npos) {
            p = star + 1;
            n = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

std::vector<fs::directory_entry> sortedEntries(const fs::path& dir) {
    std::vector<fs::directory_entry> entries;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) entries.push_back(*it);
    std::sort(entries.begin(), entries.end());
    return entries;
}

// Matches parts[i..] below `at`. '**' stands for one or more directories; as in USD, the
// walk does not descend below a directory where the rest of the pattern matched.
void matchParts(const fs::path& at, const std::vector<std::string>& parts, std::size_t i, std::vector<fs::path>& out) {
    std::error_code ec;
    if (i == parts.size()) {
        if (fs::is_regular_file(at, ec)) out.push_back(at);
        return;
    }
    const std::string& part = parts[i];
    if (part.find('*') == std::string::npos) return matchParts(at / part, parts, i + 1, out);
    for (const fs::directory_entry& entry : sortedEntries(at)) {
        if (!wildcardMatch(part, entry.path().filename().string())) continue;
        if (part != "**") {
            matchParts(entry.path(), parts, i + 1, out);
        } else if (entry.is_directory(ec) && !entry.is_symlink(ec)) {
            std::size_t before = out.size();
            matchParts(entry.path(), parts, i + 1, out);
            if (out.size() == before) matchParts(entry.path(), parts, i, out);
        }
    }
}

}  // namespace

PluginManifest parsePluginManifest(std::string_view text, const fs::path& file) {
    PluginManifest manifest;
    manifest.path = fs::absolute(file).lexically_normal();
    json top = parseJson(blankCommentLines(text), manifest.path);
    ManifestParser(manifest).parseTop(top);
    return manifest;
}

PluginManifest readPluginManifest(const fs::path& file) {
    return parsePluginManifest(readText(file), file);
}

std::vector<fs::path> expandIncludePattern(const std::string& pattern) {
    std::string file = !pattern.empty() && pattern.back() == '/' ? pattern + "plugInfo.json" : pattern;
    if (file.find('*') == std::string::npos) return {fs::path(file).lexically_normal()};
    fs::path path = fs::path(file).lexically_normal();
    std::vector<std::string> parts;
    for (const fs::path& part : path.relative_path()) parts.push_back(part.string());
    std::vector<fs::path> matches;
    matchParts(path.root_path(), parts, 0, matches);
    return matches;
}

}  // namespace opal
