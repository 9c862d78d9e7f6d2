// The farm's child processes: its own tasks (opal-bake farm-task, output appended to the
// task's log) and Slurm's commands (sbatch, squeue, scancel, output captured).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace opal {

struct ChildExit {
    int exitCode = -1;  // -1 when a signal ended it
    int signal = 0;     // the signal that ended it
    std::uint64_t peakRssBytes = 0;
    std::string out, err;  // captured output (runCommand only)

    bool ok() const { return exitCode == 0; }
    std::string describe() const;  // "exit 1" or "killed by signal 9"
};

// Runs args[0] (looked up in PATH) to the end with stdout and stderr captured. Throws
// opal::Error when it cannot be started (naming it: "sbatch not found").
ChildExit runCommand(const std::vector<std::string>& args);

// Runs `program` with args to the end, stdout and stderr appended to `log`, the
// environment extended by `environment` ("NAME=value").
ChildExit runLogged(const std::filesystem::path& program, const std::vector<std::string>& args,
                    const std::filesystem::path& log, const std::vector<std::string>& environment);

// runLogged without the wait: starts the child and returns its pid (reap it with
// waitForAnyChild), for a batch that keeps several bakes running at once.
pid_t startLogged(const std::filesystem::path& program, const std::vector<std::string>& args,
                  const std::filesystem::path& log, const std::vector<std::string>& environment);

struct EndedChild {
    pid_t pid = 0;  // 0: the wait was interrupted by a signal, nothing ended
    ChildExit exit;
};
// Waits until a child of this process ends. Throws opal::Error when there is none.
EndedChild waitForAnyChild();

// The absolute path of the running opal-bake (for tasks a scheduler starts elsewhere).
std::filesystem::path selfExecutable();

// s in single quotes for /bin/sh.
std::string shellQuoted(const std::string& s);

}  // namespace opal
