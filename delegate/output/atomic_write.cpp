#include "delegate/output/atomic_write.h"

#include "schema/error.h"

#include <cerrno>
#include <cstdio>
#include <random>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace opal {
namespace {

std::string systemMessage(int error) { return std::generic_category().message(error); }

std::string directoryOf(const std::filesystem::path& target) {
    return target.has_parent_path() ? target.parent_path().string() : std::string(".");
}

// ".<stem>.opal-tmp-<random><ext>": hidden, unique, and with the target's extension.
std::filesystem::path temporaryName(const std::filesystem::path& target,
                                    std::random_device& random) {
    char tag[16];
    std::snprintf(tag, sizeof tag, "%08x", static_cast<unsigned>(random()));
    std::string name(".");
    name += target.stem().string();
    name += ".opal-tmp-";
    name += tag;
    name += target.extension().string();
    return target.parent_path() / name;
}

// Created with O_EXCL so no other writer shares it, mode 0666 so the umask decides the
// final permissions exactly as for a plainly written file.
std::filesystem::path createTemporaryNextTo(const std::filesystem::path& target) {
    std::random_device random;
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path temporary = temporaryName(target, random);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return temporary;
        }
        if (errno != EEXIST) {
            throw Error(target.string() + ": cannot create a temporary file in '" +
                        directoryOf(target) + "': " + systemMessage(errno));
        }
    }
    throw Error(target.string() + ": cannot find an unused temporary file name in '" +
                directoryOf(target) + "'");
}

// fsync of a file, or of a directory to make a rename in it durable (some file systems
// refuse fsync on directories with EINVAL: nothing more can be done there).
void flushToDisk(const std::filesystem::path& path, int openFlags) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | openFlags);
    if (fd < 0)
        throw Error("cannot reopen '" + path.string() + "' to flush it: " + systemMessage(errno));
    const int result = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (result != 0 && !(openFlags & O_DIRECTORY && error == EINVAL)) {
        throw Error("cannot flush '" + path.string() + "' to disk: " + systemMessage(error));
    }
}

}  // namespace

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& writeTemporary) {
    const std::filesystem::path temporary = createTemporaryNextTo(target);
    try {
        writeTemporary(temporary);
        flushToDisk(temporary, 0);
        std::error_code renameError;
        std::filesystem::rename(temporary, target, renameError);
        if (renameError) throw Error("cannot replace the file: " + renameError.message());
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw Error(target.string() + ": " + e.what());
    }
    try {
        flushToDisk(directoryOf(target), O_DIRECTORY);
    } catch (const Error& e) {
        throw Error(target.string() + ": written, but " + e.what());
    }
}

}  // namespace opal
