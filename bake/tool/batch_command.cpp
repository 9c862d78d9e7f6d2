#include "bake/tool/batch_command.h"

#include "bake/farm/child_process.h"
#include "bake/tool/batch_manifest.h"
#include "schema/asset/bake_id.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <nlohmann/json.hpp>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
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

// Starts opal-bake for one entry (with `farmArgs`), its output to STEM.batch.log (this
// attempt's only, since the summary quotes its last line); returns its pid.
pid_t startBake(const BatchEntry& e, const std::vector<std::string>& farmArgs) {
    std::vector<std::string> args = {e.input, "-o", e.output.string(), "--quiet"};
    args.insert(args.end(), farmArgs.begin(), farmArgs.end());
    args.insert(args.end(), e.args.begin(), e.args.end());
    const std::filesystem::path log = withSuffix(e.output, ".batch.log");
    std::error_code ignored;
    std::filesystem::remove(log, ignored);
    return startLogged(selfExecutable(), args, log, {});
}

// The exit code, 128 + the signal that ended it.
int exitCode(const ChildExit& exit) { return exit.exitCode >= 0 ? exit.exitCode : 128 + exit.signal; }

std::string lastLine(const std::filesystem::path& file) {
    std::istringstream text(readFile(file));
    std::string line, last;
    while (std::getline(text, line))
        if (!line.empty()) last = line;
    return last;
}

bool interrupted(int code) { return code == 130 || code == 143; }

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// An asset to bake (or skipped or failed before any attempt, `done`).
struct Pending {
    Outcome outcome;
    std::uint64_t key = 0;
    Clock::time_point start;
    bool done = false;
};

Pending prepare(const BatchEntry& e, std::uint64_t tool) {
    Pending p;
    p.outcome.name = e.output.string();
    p.start = Clock::now();
    try {
        p.key = bakeKey(tool, e);
        std::filesystem::create_directories(e.output.parent_path());
    } catch (const std::exception& error) {
        p.outcome.error = error.what();
        p.done = true;
        return p;
    }
    if (unchanged(e, p.key)) {
        p.outcome.status = Status::Skipped;
        p.done = true;
    } else {
        std::filesystem::remove(withSuffix(e.output, ".batch"));
    }
    return p;
}

// The asset's figures once it is baked, skipped or failed for good.
void finish(const BatchEntry& e, Pending& p) {
    Outcome& o = p.outcome;
    // The key that lets the next batch skip this asset, written atomically; without it the
    // asset is only baked again, so a failure to write it is a warning.
    if (o.status == Status::Baked) try {
            writeFileAtomically(withSuffix(e.output, ".batch"), formatBakeId(p.key) + "\n");
        } catch (const Error& error) {
            std::cerr << "opal-bake batch: warning: " << error.what() << " (the asset will be baked again next time)\n";
        }
    o.seconds = secondsSince(p.start);
    std::error_code error;
    if (o.status != Status::Failed) o.sidecarBytes = std::filesystem::file_size(sidecarOf(e.output), error);
    p.done = true;
}

// Runs the pending assets' bakes, at most `slots` at once, each retried once; a Slurm
// batch runs them all at once (each process mostly waits for its jobs). On SIGINT/SIGTERM
// the running bakes are stopped (SIGTERM) and Cancelled is thrown.
class BakeQueue {
public:
    BakeQueue(const std::vector<BatchEntry>& entries, std::vector<Pending>& pending,
              std::vector<std::string> farmArgs, std::size_t slots, bool quiet)
        : entries_(entries), pending_(pending), farmArgs_(std::move(farmArgs)), slots_(slots), quiet_(quiet) {
        for (std::size_t i = 0; i < pending_.size(); ++i)
            if (!pending_[i].done) waiting_.push_back(i);
    }

    void run(const CancelToken& cancel) {
        while (!waiting_.empty() || !running_.empty()) {
            if (running_.empty()) cancel.throwIfRequested();
            while (!waiting_.empty() && running_.size() < slots_) {
                const std::size_t i = waiting_.front();
                waiting_.pop_front();
                start(i);
            }
            if (running_.empty()) continue;
            const EndedChild ended = waitForAnyChild();
            if (cancel.requested()) {
                stopAll();
                throw Cancelled();
            }
            if (ended.pid == 0) continue;
            const auto it = running_.find(ended.pid);
            if (it == running_.end()) continue;
            const std::size_t i = it->second;
            running_.erase(it);
            onEnded(i, exitCode(ended.exit));
        }
    }

private:
    void start(std::size_t i) {
        Outcome& o = pending_[i].outcome;
        ++o.attempts;
        if (!quiet_) std::fprintf(stderr, "opal-bake batch: %s\n", o.name.c_str());
        try {
            running_.emplace(startBake(entries_[i], farmArgs_), i);
        } catch (const Error& error) {
            o.error = error.what();
            finish(entries_[i], pending_[i]);
        }
    }

    void onEnded(std::size_t i, int code) {
        if (interrupted(code)) {
            stopAll();
            throw Cancelled();
        }
        Pending& p = pending_[i];
        if (code != 0 && p.outcome.attempts < 2) {  // retried at once: a farm bake resumes
            waiting_.push_front(i);
            return;
        }
        if (code != 0)
            p.outcome.error = "exit " + std::to_string(code) + ": " + lastLine(withSuffix(entries_[i].output, ".batch.log"));
        else
            p.outcome.status = Status::Baked;
        finish(entries_[i], p);
    }

    void stopAll() {
        for (const auto& [pid, i] : running_) kill(pid, SIGTERM);
        while (!running_.empty())
            if (const EndedChild e = waitForAnyChild(); e.pid != 0) running_.erase(e.pid);
    }

    const std::vector<BatchEntry>& entries_;
    std::vector<Pending>& pending_;
    const std::vector<std::string> farmArgs_;
    const std::size_t slots_;
    const bool quiet_;
    std::deque<std::size_t> waiting_;
    std::map<pid_t, std::size_t> running_;
};

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
    writeFileAtomically(file, j.dump(2) + "\n");
}

}  // namespace

BatchCommand::BatchCommand(CLI::App& app) {
    command_ = app.add_subcommand("batch", "bake every asset a manifest lists, skipping unchanged ones");
    command_->add_option("manifest", manifest_, "MANIFEST.json: {\"assets\": [{\"input\", \"output\", \"args\"}]}")
        ->required();
    command_->add_option("--json", json_, "write the summary as JSON to this file");
    command_->add_flag("-q,--quiet", quiet_, "no table on stdout");
    command_->add_option("--farm", farm_, "bake each asset as farm tasks: local (here, one asset at a time) or slurm "
                                          "(every asset submitted at once)")
        ->check(CLI::IsMember({"local", "slurm"}));
    command_->add_option("--shards", shards_, "farm: each asset's --shards")->check(CLI::Range(1u, 4096u));
    command_->add_option("--partition", partition_, "farm slurm: each asset's --partition");
    command_->add_option("--mem", memory_, "farm slurm: each asset's --mem");
    command_->add_option("--time", time_, "farm slurm: each asset's --time");
}

void BatchCommand::validate() const {
    if (!chosen()) return;
    if (farm_.empty() && shards_)
        throw CLI::ValidationError("batch --shards", "is for a batch with --farm local or slurm");
    if (farm_ != "slurm" && (!partition_.empty() || !memory_.empty() || !time_.empty()))
        throw CLI::ValidationError("batch --farm local", "--partition, --mem and --time are for --farm slurm");
}

std::vector<std::string> BatchCommand::farmArgs() const {
    if (farm_.empty()) return {};
    std::vector<std::string> args = {"--farm", farm_};
    if (shards_) args.insert(args.end(), {"--shards", std::to_string(*shards_)});
    if (farm_ == "slurm") args.push_back("--wait");
    for (const auto& [option, value] : {std::pair{"--partition", partition_}, {"--mem", memory_}, {"--time", time_}})
        if (!value.empty()) args.insert(args.end(), {option, value});
    return args;
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
    std::vector<Pending> pending;
    for (const BatchEntry& e : entries) pending.push_back(prepare(e, tool));
    const std::size_t slots = farm_ == "slurm" ? entries.size() : 1;
    BakeQueue(entries, pending, farmArgs(), slots, quiet_).run(cancel);
    std::vector<Outcome> outcomes;
    for (const Pending& p : pending) outcomes.push_back(p.outcome);
    if (!json_.empty()) writeJson(json_, outcomes);
    if (!quiet_) printTable(outcomes, std::cout);
    const bool failed = std::any_of(outcomes.begin(), outcomes.end(), [](const Outcome& o) { return o.status == Status::Failed; });
    return failed ? 1 : 0;
}

}  // namespace opal
