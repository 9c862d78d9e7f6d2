// Running a piece of a test where a test process cannot put itself: on a full disk, or
// without the privileges of root (CI runs the tests as root, for whom permissions do not
// apply). The piece runs in a forked child, which sets up its restriction first:
//
// - SmallDisk: a tmpfs of a few KiB mounted over a folder in a mount namespace of the
//   child's own (so nobody else sees it and it vanishes with the child); writes past its
//   size fail with ENOSPC, for real. Where mount namespaces are refused (an unprivileged
//   container), the child limits its file size instead (RLIMIT_FSIZE): writes then fail
//   with EFBIG, just as really. `errorText` says which.
// - Unprivileged: the child drops to the user and group nobody (65534) for good.
//
// The piece returns a text (what it observed); the parent gets it back through a pipe
// and makes its assertions, since a forked child's test failures would be lost.
#pragma once

#include <grp.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>

namespace opal::test {

struct SmallDisk {
    std::filesystem::path folder;  // an existing, empty folder
    std::size_t bytes = 64 * 1024;
};

struct ChildReport {
    bool ran = false;        // the child set up its restriction and ran the piece
    std::string text;        // what the piece returned, or why it could not run
    std::string errorText;   // SmallDisk: strerror of the error a full disk gives here
};

namespace detail {

inline void sendAndExit(int fd, const std::string& text, int code) {
    std::size_t sent = 0;
    while (sent < text.size()) {
        const ssize_t n = ::write(fd, text.data() + sent, text.size() - sent);
        if (n <= 0) break;
        sent += std::size_t(n);
    }
    ::_exit(code);
}

// 0: a private tmpfs is mounted (ENOSPC); 1: the file size is limited (EFBIG); -1: neither.
inline int restrictDisk(const SmallDisk& disk) {
    if (::unshare(CLONE_NEWNS) == 0 && ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0) {
        const std::string options = "size=" + std::to_string(disk.bytes) + ",mode=0755";
        if (::mount("tmpfs", disk.folder.c_str(), "tmpfs", 0, options.c_str()) == 0) return 0;
    }
    std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
    const rlimit limit{disk.bytes, disk.bytes};
    return ::setrlimit(RLIMIT_FSIZE, &limit) == 0 ? 1 : -1;
}

inline ChildReport runInChild(const std::function<bool(std::string&)>& restrict,
                              const std::function<std::string()>& piece) {
    int fds[2];
    if (::pipe(fds) != 0) return {false, "pipe failed", ""};
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        std::string why;
        if (!restrict(why)) sendAndExit(fds[1], why, 2);
        std::string text;
        try {
            text = piece();
        } catch (const std::exception& e) {
            text = std::string("unexpected exception: ") + e.what();
        }
        sendAndExit(fds[1], text, 0);
    }
    ::close(fds[1]);
    ChildReport report;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) report.text.append(buffer, std::size_t(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    report.ran = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (!WIFEXITED(status)) report.text += " (the child died by signal " + std::to_string(WTERMSIG(status)) + ")";
    return report;
}

}  // namespace detail

// Runs `piece` in a child where `disk.folder` holds at most `disk.bytes`.
inline ChildReport onSmallDisk(const SmallDisk& disk, const std::function<std::string()>& piece) {
    int mode = -1;
    ChildReport report = detail::runInChild(
        [&](std::string& why) {
            mode = detail::restrictDisk(disk);
            why = "cannot make a small disk: " + std::string(std::strerror(errno));
            return mode >= 0;
        },
        [&] { return std::to_string(mode) + "\n" + piece(); });  // the child's mode, first
    if (!report.ran) return report;
    const std::size_t end = report.text.find('\n');
    report.errorText = std::strerror(report.text.substr(0, end) == "0" ? ENOSPC : EFBIG);
    report.text.erase(0, end + 1);
    return report;
}

// Runs `piece` in a child that has dropped to user and group nobody (65534).
inline ChildReport unprivileged(const std::function<std::string()>& piece) {
    return detail::runInChild(
        [](std::string& why) {
            if (::setgroups(0, nullptr) == 0 && ::setresgid(65534, 65534, 65534) == 0 &&
                ::setresuid(65534, 65534, 65534) == 0)
                return true;
            why = "cannot drop privileges: " + std::string(std::strerror(errno));
            return ::geteuid() != 0;  // already unprivileged: nothing to drop
        },
        piece);
}

}  // namespace opal::test
