#include "schema/usd/atomic_file.h"

#include "schema/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <random>
#include <string>
#include <unistd.h>

namespace opal {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int err) {
    throw opal::Error(path.string() + ": cannot write file: " + what + ": " + std::strerror(err));
}

std::filesystem::path temporaryBeside(const std::filesystem::path& path) {
    std::random_device entropy;
    std::uniform_int_distribution<unsigned long long> digits;
    char suffix[20];
    std::snprintf(suffix, sizeof suffix, "%016llx", digits(entropy));
    std::filesystem::path tmp = path;
    tmp += std::string(".tmp-") + suffix;
    return tmp;
}

// Opens a new temporary file (O_EXCL, mode 0666 & ~umask).
int openTemporary(const std::filesystem::path& path, std::filesystem::path& tmp) {
    for (int attempt = 0; attempt < 8; ++attempt) {
        tmp = temporaryBeside(path);
        int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            return fd;
        }
        if (errno != EEXIST) {
            fail(path, "creating temporary file '" + tmp.string() + "'", errno);
        }
    }
    fail(path, "creating a temporary file", EEXIST);
}

void writeAll(int fd, std::string_view bytes, const std::filesystem::path& path) {
    while (!bytes.empty()) {
        ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            fail(path, "writing", n < 0 ? errno : EIO);
        }
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
}

// Makes the rename itself durable. Best effort: the file is complete either way.
void syncDirectory(const std::filesystem::path& path) {
    std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    std::filesystem::path tmp;
    int fd = openTemporary(path, tmp);
    try {
        writeAll(fd, bytes, path);
        if (::fsync(fd) != 0) {
            fail(path, "flushing to disk", errno);
        }
        if (::close(fd) != 0) {
            fd = -1;
            fail(path, "closing", errno);
        }
        fd = -1;
        if (std::rename(tmp.c_str(), path.c_str()) != 0) {
            fail(path, "renaming '" + tmp.string() + "' over it", errno);
        }
        syncDirectory(path);
    } catch (...) {
        if (fd >= 0) {
            ::close(fd);
        }
        ::unlink(tmp.c_str());
        throw;
    }
}

}  // namespace opal
