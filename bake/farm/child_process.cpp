#include "bake/farm/child_process.h"

#include "schema/error.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>

extern char** environ;

namespace opal {

namespace {

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (std::string& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

ChildExit exitOf(int status, const rusage& usage) {
    ChildExit e;
    if (WIFEXITED(status)) e.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) e.signal = WTERMSIG(status);
    e.peakRssBytes = std::uint64_t(usage.ru_maxrss) * 1024;
    return e;
}

ChildExit reap(pid_t pid) {
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    return exitOf(status, usage);
}

// Reads both pipes until both close.
void drain(int outFd, int errFd, std::string& out, std::string& err) {
    pollfd fds[2] = {{outFd, POLLIN, 0}, {errFd, POLLIN, 0}};
    std::string* into[2] = {&out, &err};
    int open = 2;
    while (open > 0) {
        if (poll(fds, 2, -1) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buf[4096];
            const ssize_t n = read(fds[i].fd, buf, sizeof buf);
            if (n > 0) {
                into[i]->append(buf, std::size_t(n));
            } else if (n == 0 || errno != EINTR) {
                close(fds[i].fd);
                fds[i].fd = -1;
                --open;
            }
        }
    }
}

}  // namespace

std::string ChildExit::describe() const {
    if (signal) return "killed by signal " + std::to_string(signal);
    return "exit " + std::to_string(exitCode);
}

ChildExit runCommand(const std::vector<std::string>& args) {
    int out[2], err[2];
    if (pipe2(out, O_CLOEXEC) != 0) throw Error("cannot create a pipe for " + args[0]);
    if (pipe2(err, O_CLOEXEC) != 0) {
        close(out[0]);
        close(out[1]);
        throw Error("cannot create a pipe for " + args[0]);
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
    std::vector<std::string> copy = args;
    std::vector<char*> argv = pointers(copy);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    close(err[1]);
    if (rc != 0) {
        close(out[0]);
        close(err[0]);
        throw Error(args[0] + ": cannot run it: " + std::strerror(rc) +
                    (rc == ENOENT ? " (is Slurm's client installed and on PATH?)" : ""));
    }
    std::string o, e;
    drain(out[0], err[0], o, e);
    ChildExit result = reap(pid);
    result.out = std::move(o);
    result.err = std::move(e);
    return result;
}

pid_t startLogged(const std::filesystem::path& program, const std::vector<std::string>& args,
                  const std::filesystem::path& log, const std::vector<std::string>& environment) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::vector<std::string> argStrings = args;
    argStrings.insert(argStrings.begin(), program.string());
    std::vector<char*> argv = pointers(argStrings);
    std::vector<std::string> envStrings;
    const auto overridden = [&](std::string_view entry) {  // getenv takes the first of two
        for (const std::string& e : environment)
            if (entry.substr(0, entry.find('=') + 1) == std::string_view(e).substr(0, e.find('=') + 1)) return true;
        return false;
    };
    for (char** e = environ; *e; ++e)
        if (!overridden(*e)) envStrings.emplace_back(*e);
    envStrings.insert(envStrings.end(), environment.begin(), environment.end());
    std::vector<char*> envp = pointers(envStrings);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw Error(program.string() + ": cannot run it: " + std::strerror(rc));
    return pid;
}

ChildExit runLogged(const std::filesystem::path& program, const std::vector<std::string>& args,
                    const std::filesystem::path& log, const std::vector<std::string>& environment) {
    return reap(startLogged(program, args, log, environment));
}

EndedChild waitForAnyChild() {
    int status = 0;
    rusage usage{};
    const pid_t pid = wait4(-1, &status, 0, &usage);
    if (pid < 0 && errno == EINTR) return {};
    if (pid < 0) throw Error(std::string("waiting for a child process: ") + std::strerror(errno));
    return {pid, exitOf(status, usage)};
}

std::filesystem::path selfExecutable() { return std::filesystem::read_symlink("/proc/self/exe"); }

std::string shellQuoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace opal
