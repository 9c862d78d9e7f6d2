// Helpers for the bake pipeline and opal-bake CLI tests: scratch folders, whole-file
// reads, and a child process (posix_spawn) with its stdout and stderr read through pipes
// under a deadline, so that a test never hangs on a child that does not finish.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace opal::test {

// A fresh folder under the system temporary folder, removed with everything in it.
class ScratchDir {
public:
    ScratchDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "opal-bake-test-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed: " + std::string(std::strerror(errno)));
        path_ = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

    // File names in the folder, sorted.
    std::vector<std::string> list() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(path_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path path_;
};

inline std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

// The sidecar file name a baked layer names in opal:sidecar ("candle.<bake id>.opal").
inline std::string sidecarNamedBy(const std::filesystem::path& usda) {
    const std::string text = readBytes(usda);
    const std::string key = "opal:sidecar = @";
    const std::size_t start = text.find(key);
    if (start == std::string::npos) throw std::runtime_error(usda.string() + " names no sidecar");
    const std::size_t end = text.find('@', start + key.size());
    std::string name = text.substr(start + key.size(), end - start - key.size());
    if (name.starts_with("./")) name.erase(0, 2);
    return name;
}

// The command line `a` followed by `b`.
inline std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

inline std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
}

// A child process with stdout and stderr on pipes. The destructor SIGKILLs and reaps a
// child that is still running.
class ChildProcess {
public:
    using Clock = std::chrono::steady_clock;

    // `environment`: "NAME=value" entries added to the test's own environment.
    explicit ChildProcess(const std::vector<std::string>& args, const std::vector<std::string>& environment = {}) {
        int out[2], err[2];
        if (pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0) throw std::runtime_error("pipe2 failed");
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
        posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
        // The child starts with default SIGINT/SIGTERM handling and nothing blocked,
        // whatever the test runner does with them.
        posix_spawnattr_t attr;
        posix_spawnattr_init(&attr);
        sigset_t none, defaults;
        sigemptyset(&none);
        sigemptyset(&defaults);
        sigaddset(&defaults, SIGINT);
        sigaddset(&defaults, SIGTERM);
        sigaddset(&defaults, SIGPIPE);
        posix_spawnattr_setsigmask(&attr, &none);
        posix_spawnattr_setsigdefault(&attr, &defaults);
        posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
        std::vector<char*> argv;
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        std::vector<char*> envp;
        for (char** e = environ; *e; ++e) envp.push_back(*e);
        for (const std::string& e : environment) envp.push_back(const_cast<char*>(e.c_str()));
        envp.push_back(nullptr);
        const int rc = posix_spawn(&pid_, argv[0], &actions, &attr, argv.data(), envp.data());
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attr);
        close(out[1]);
        close(err[1]);
        outFd_ = out[0];
        errFd_ = err[0];
        if (rc != 0) {
            closePipes();
            throw std::runtime_error("posix_spawn " + args[0] + ": " + std::strerror(rc));
        }
    }

    ~ChildProcess() {
        if (running()) {
            kill(pid_, SIGKILL);
            int status = 0;
            waitpid(pid_, &status, 0);
        }
        closePipes();
    }
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    bool running() const { return pid_ > 0 && !reaped_; }
    pid_t pid() const { return pid_; }
    void signal(int sig) const {
        if (running()) kill(pid_, sig);
    }

    // Reads the pipes until stderr contains `text`; false on deadline or end of output.
    bool waitForStderr(const std::string& text, Clock::duration timeout) {
        const auto deadline = Clock::now() + timeout;
        while (err_.find(text) == std::string::npos) {
            if (!pump(deadline)) return err_.find(text) != std::string::npos;
        }
        return true;
    }

    // Reads everything and reaps the child; on deadline SIGKILLs it and returns false.
    bool wait(Clock::duration timeout) {
        const auto deadline = Clock::now() + timeout;
        while (pump(deadline)) {
        }
        if (outFd_ >= 0 || errFd_ >= 0) {  // deadline with the pipes still open
            kill(pid_, SIGKILL);
            reap();
            timedOut_ = true;
            return false;
        }
        // Pipes closed: the child has exited (or closed them); give it until the deadline.
        while (!reaped_) {
            int status = 0;
            const pid_t r = waitpid(pid_, &status, WNOHANG);
            if (r == pid_) {
                record(status);
                break;
            }
            if (Clock::now() > deadline) {
                kill(pid_, SIGKILL);
                reap();
                timedOut_ = true;
                return false;
            }
            usleep(2000);
        }
        return true;
    }

    bool timedOut() const { return timedOut_; }
    bool exited() const { return reaped_ && WIFEXITED(status_); }
    // The exit code when the child exited normally; -1 when a signal ended it.
    int exitCode() const { return reaped_ && WIFEXITED(status_) ? WEXITSTATUS(status_) : -1; }
    int termSignal() const { return reaped_ && WIFSIGNALED(status_) ? WTERMSIG(status_) : 0; }
    const std::string& out() const { return out_; }
    const std::string& err() const { return err_; }

private:
    // One poll round; false when both pipes are closed or the deadline passed.
    bool pump(Clock::time_point deadline) {
        if (outFd_ < 0 && errFd_ < 0) return false;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return false;
        pollfd fds[2] = {{outFd_, POLLIN, 0}, {errFd_, POLLIN, 0}};
        const int ready = poll(fds, 2, int(std::min<long long>(left, 1000)));
        if (ready < 0 && errno != EINTR) return false;
        drain(fds[0], outFd_, out_);
        drain(fds[1], errFd_, err_);
        return true;
    }

    static void drain(const pollfd& p, int& fd, std::string& into) {
        if (fd < 0 || !(p.revents & (POLLIN | POLLHUP | POLLERR))) return;
        char buf[4096];
        const ssize_t n = read(fd, buf, sizeof buf);
        if (n > 0) {
            into.append(buf, std::size_t(n));
        } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
            close(fd);
            fd = -1;
        }
    }

    void reap() {
        int status = 0;
        if (waitpid(pid_, &status, 0) == pid_) record(status);
    }
    void record(int status) {
        status_ = status;
        reaped_ = true;
    }
    void closePipes() {
        if (outFd_ >= 0) close(outFd_);
        if (errFd_ >= 0) close(errFd_);
        outFd_ = errFd_ = -1;
    }

    pid_t pid_ = -1;
    int outFd_ = -1, errFd_ = -1;
    int status_ = 0;
    bool reaped_ = false, timedOut_ = false;
    std::string out_, err_;
};

// Runs a command to completion (bounded by `timeout`).
struct RunResult {
    int exitCode = -1;  // -1: ended by a signal or timed out
    int termSignal = 0;  // the signal that ended it, if one did
    bool timedOut = false;
    std::string out, err;
};

inline RunResult run(const std::vector<std::string>& args, std::chrono::seconds timeout = std::chrono::seconds(120),
                     const std::vector<std::string>& environment = {}) {
    ChildProcess child(args, environment);
    RunResult r;
    r.timedOut = !child.wait(timeout);
    r.exitCode = child.exitCode();
    r.termSignal = child.termSignal();
    r.out = child.out();
    r.err = child.err();
    return r;
}

}  // namespace opal::test
