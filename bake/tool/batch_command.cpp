#include "bake/tool/batch_command.h"

#include "bake/farm/child_process.h"
#include "bake/tool/batch_manifest.h"
#include "schema/asset/bake_id.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace opal {
namespace {

enum class Status { Baked, Skipped, Failed };

struct Outcome {
    std::string name;
    Status status = Status::Failed;
    int attempts = 0;
    double seconds = 0.0;
    std::uintmax_t sidecarBytes = 0;
    std::string error;
};

const char* statusName(Status s) { return s == Status::Baked ? "baked" : s == Status::Skipped ? "skipped" : "failed"; }

std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void hashText(Xxh64& hash, const std::string& text) {
    hash.update(std::as_bytes(std::span(text.data(), text.size())));
    const char separator = '\n';
    hash.update(std::as_bytes(std::span(&separator, 1)));
}

// XXH64 of opal-bake's bytes (hashed once), the input's bytes or built-in name, and the args.
std::uint64_t bakeKey(std::uint64_t tool, const BatchEntry& e) {
    Xxh64 hash;
    hashText(hash, formatBakeId(tool));
    hashText(hash, e.input.starts_with("builtin:") ? e.input : readFile(e.input));
    for (const std::string& arg : e.args) hashText(hash, arg);
    return hash.digest();
}

std::filesystem::path withSuffix(const std::filesystem::path& stem, const std::string& suffix) {
    return stem.string() + suffix;
}

// The sidecar the layer names (opal:sidecar = @./NAME@), empty when none can be read.
std::filesystem::path sidecarOf(const std::filesystem::path& stem) {
    const std::string layer = readFile(withSuffix(stem, ".usda")), tag = "opal:sidecar = @";
    const std::size_t at = layer.find(tag);
    if (at == std::string::npos) return {};
    const std::size_t end = layer.find('@', at + tag.size());
    if (end == std::string::npos) return {};
    return stem.parent_path() / layer.substr(at + tag.size(), end - at - tag.size());
}

bool unchanged(const BatchEntry& e, std::uint64_t key) {
    std::error_code error;
    const std::filesystem::path sidecar = sidecarOf(e.output);
    if (sidecar.empty() || !std::filesystem::is_regular_file(sidecar, error)) return false;
    return readFile(withSuffix(e.output, ".batch")) == formatBakeId(key) + "\n";
}

// Runs opal-bake for one entry, its output to STEM.batch.log (this attempt's only, since
// the summary quotes its last line); returns the exit code, 128 + the signal that ended it.
int bakeOnce(const BatchEntry& e) {
    std::vector<std::string> args = {e.input, "-o", e.output.string(), "--quiet"};
    args.insert(args.end(), e.args.begin(), e.args.end());
    const std::filesystem::path log = withSuffix(e.output, ".batch.log");
    std::error_code ignored;
    std::filesystem::remove(log, ignored);
    const ChildExit exit = runLogged(selfExecutable(), args, log, {});
    return exit.exitCode >= 0 ? exit.exitCode : 128 + exit.signal;
}

std::string lastLine(const std::filesystem::path& file) {
    std::istringstream text(readFile(file));
    std::string line, last;
    while (std::getline(text, line))
        if (!line.empty()) last = line;
    return last;
}

bool interrupted(int code) { return code == 130 || code == 143; }

Outcome bakeEntry(const BatchEntry& e, std::uint64_t tool) {
    Outcome o;
    o.name = e.output.string();
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t key = 0;
    try {
        key = bakeKey(tool, e);
        std::filesystem::create_directories(e.output.parent_path());
    } catch (const std::exception& error) {
        o.error = error.what();
        return o;
    }
    if (unchanged(e, key)) {
        o.status = Status::Skipped;
    } else {
        std::filesystem::remove(withSuffix(e.output, ".batch"));
        int code = 1;
        for (o.attempts = 1; o.attempts <= 2; ++o.attempts) {
            try {
                code = bakeOnce(e);
            } catch (const Error& error) {
                o.error = error.what();
                return o;
            }
            if (code == 0 || interrupted(code)) break;
        }
        o.attempts = std::min(o.attempts, 2);
        if (interrupted(code)) throw Cancelled();
        if (code != 0) {
            o.error = "exit " + std::to_string(code) + ": " + lastLine(withSuffix(e.output, ".batch.log"));
        } else {
            std::ofstream(withSuffix(e.output, ".batch")) << formatBakeId(key) << '\n';
            o.status = Status::Baked;
        }
    }
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::error_code error;
    if (o.status != Status::Failed) o.sidecarBytes = std::filesystem::file_size(sidecarOf(e.output), error);
    return o;
}

void printTable(std::vector<Outcome> outcomes, std::ostream& out) {
    std::stable_sort(outcomes.begin(), outcomes.end(),
                     [](const Outcome& a, const Outcome& b) { return (a.status == Status::Failed) > (b.status == Status::Failed); });
    char row[512];
    std::snprintf(row, sizeof row, "%-8s %-8s %8s %10s  %s\n", "status", "attempts", "time s", "size MB", "asset / error");
    out << row;
    for (const Outcome& o : outcomes) {
        std::snprintf(row, sizeof row, "%-8s %-8d %8.1f %10.2f  %s\n", statusName(o.status), o.attempts, o.seconds,
                      double(o.sidecarBytes) / 1e6, o.name.c_str());
        out << row;
        if (!o.error.empty()) out << "         " << o.error << '\n';
    }
}

void writeJson(const std::filesystem::path& file, const std::vector<Outcome>& outcomes) {
    nlohmann::ordered_json j;
    j["assets"] = nlohmann::json::array();
    int failed = 0;
    for (const Outcome& o : outcomes) {
        j["assets"].push_back({{"asset", o.name}, {"status", statusName(o.status)}, {"attempts", o.attempts},
                               {"seconds", o.seconds}, {"sidecarBytes", o.sidecarBytes}, {"error", o.error}});
        failed += o.status == Status::Failed;
    }
    j["failed"] = failed;
    const std::filesystem::path temporary = withSuffix(file, ".tmp");
    std::ofstream(temporary) << j.dump(2) << '\n';
    std::filesystem::rename(temporary, file);
}

}  // namespace

BatchCommand::BatchCommand(CLI::App& app) {
    command_ = app.add_subcommand("batch", "bake every asset a manifest lists, skipping unchanged ones");
    command_->add_option("manifest", manifest_, "MANIFEST.json: {\"assets\": [{\"input\", \"output\", \"args\"}]}")
        ->required();
    command_->add_option("--json", json_, "write the summary as JSON to this file");
    command_->add_flag("-q,--quiet", quiet_, "no table on stdout");
}

int BatchCommand::run(const CancelToken& cancel) const {
    std::vector<BatchEntry> entries;
    try {
        entries = readBatchManifest(manifest_);
    } catch (const Error& e) {
        std::fprintf(stderr, "opal-bake: error: %s\n", e.what());
        return 1;
    }
    const std::string self = readFile("/proc/self/exe");
    const std::uint64_t tool = xxh64(std::as_bytes(std::span(self.data(), self.size())));
    std::vector<Outcome> outcomes;
    for (const BatchEntry& e : entries) {
        cancel.throwIfRequested();
        if (!quiet_) std::fprintf(stderr, "opal-bake batch: %s\n", e.output.string().c_str());
        outcomes.push_back(bakeEntry(e, tool));
    }
    if (!json_.empty()) writeJson(json_, outcomes);
    if (!quiet_) printTable(outcomes, std::cout);
    const bool failed = std::any_of(outcomes.begin(), outcomes.end(), [](const Outcome& o) { return o.status == Status::Failed; });
    return failed ? 1 : 0;
}

}  // namespace opal
