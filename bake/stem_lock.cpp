#include "bake/stem_lock.h"

#include "schema/error.h"

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace opal {
namespace {

std::string holderOf(int fd) {
    char text[32] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    return n > 0 ? std::string(text, std::size_t(n)) : std::string();
}

// Whether `fd` is still the file at `path`: a holder that released the lock removed the
// file, so a lock taken on that removed file would exclude nobody.
bool stillAt(int fd, const std::filesystem::path& path) {
    struct stat opened {}, named {};
    return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 && opened.st_dev == named.st_dev &&
           opened.st_ino == named.st_ino;
}

}  // namespace

StemLock::StemLock(AssetStem stem) : stem_(std::move(stem)) {
    const std::filesystem::path path = stem_.lockFile();
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
        if (fd < 0) throw Error(path.string() + ": cannot create the lock file: " + std::strerror(errno));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            const std::string holder = holderOf(fd);
            ::close(fd);
            if (error != EWOULDBLOCK) throw Error(path.string() + ": cannot lock: " + std::strerror(error));
            throw Error(path.string() + ": another opal-bake" + (holder.empty() ? "" : " (pid " + holder + ")") +
                        " is writing " + stem_.layer().string() + " and its sidecar; wait until it has finished");
        }
        if (stillAt(fd, path)) {
            const std::string pid = std::to_string(::getpid());
            // For a contender's message only: a failed write costs nothing else.
            const bool recorded = ::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.data(), pid.size(), 0) == ssize_t(pid.size());
            static_cast<void>(recorded);
            fd_ = fd;
            return;
        }
        ::close(fd);
    }
    throw Error(path.string() + ": cannot lock: the lock file keeps being replaced");
}

StemLock::~StemLock() {
    ::unlink(stem_.lockFile().c_str());  // while still held: see stillAt
    ::close(fd_);
}

}  // namespace opal
