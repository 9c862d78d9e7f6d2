#include "bake/tool/batch_manifest.h"

#include "schema/error.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>

namespace opal {
namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::filesystem::path& manifest, const std::string& where, const std::string& what) {
    throw Error(manifest.string() + ": " + where + ": " + what);
}

std::string stringField(const std::filesystem::path& manifest, const Json& entry, const std::string& where,
                        const char* name) {
    const auto it = entry.find(name);
    if (it == entry.end() || !it->is_string() || it->get<std::string>().empty())
        fail(manifest, where + "." + name, "missing, or not a non-empty string");
    return it->get<std::string>();
}

std::vector<std::string> argsOf(const std::filesystem::path& manifest, const Json& entry, const std::string& where) {
    std::vector<std::string> args;
    const auto it = entry.find("args");
    if (it == entry.end()) return args;
    if (!it->is_array()) fail(manifest, where + ".args", "not an array of strings");
    for (std::size_t i = 0; i < it->size(); ++i) {
        const Json& arg = (*it)[i];
        if (!arg.is_string()) fail(manifest, where + ".args[" + std::to_string(i) + "]", "not a string");
        const std::string text = arg.get<std::string>();
        for (const char* own : {"-o", "--output", "--json", "-q", "--quiet", "--farm", "--shards", "--partition",
                                "--mem", "--time", "--wait"})
            if (text == own || text.starts_with(std::string(own) + "="))
                fail(manifest, where + ".args[" + std::to_string(i) + "]", "'" + text + "' is set by the batch");
        args.push_back(text);
    }
    return args;
}

}  // namespace

std::vector<BatchEntry> readBatchManifest(const std::filesystem::path& manifest) {
    std::ifstream in(manifest);
    if (!in) throw Error(manifest.string() + ": cannot be read");
    Json root;
    try {
        root = Json::parse(in);
    } catch (const Json::parse_error& e) {
        throw Error(manifest.string() + ": not JSON: " + e.what());
    }
    if (!root.is_object() || !root.contains("assets") || !root["assets"].is_array())
        fail(manifest, "assets", "expected an object with an array \"assets\"");
    const std::filesystem::path folder = manifest.parent_path();
    std::vector<BatchEntry> entries;
    std::set<std::filesystem::path> stems;
    for (std::size_t i = 0; i < root["assets"].size(); ++i) {
        const Json& entry = root["assets"][i];
        const std::string where = "assets[" + std::to_string(i) + "]";
        if (!entry.is_object()) fail(manifest, where, "not an object");
        BatchEntry e;
        e.input = stringField(manifest, entry, where, "input");
        if (!e.input.starts_with("builtin:")) e.input = (folder / e.input).lexically_normal().string();
        e.output = (folder / stringField(manifest, entry, where, "output")).lexically_normal();
        e.args = argsOf(manifest, entry, where);
        if (!stems.insert(e.output).second) fail(manifest, where + ".output", "a second asset writes " + e.output.string());
        entries.push_back(std::move(e));
    }
    return entries;
}

}  // namespace opal
