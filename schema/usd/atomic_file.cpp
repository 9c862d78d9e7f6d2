#include "schema/usd/atomic_file.h"

#include "schema/error.h"
#include "schema/usd/crash_point.h"

#include <cerrno>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace opal {
namespace {

constexpr std::size_t kBufferBytes = 1 << 20;

// "<target file name>.tmp-<pid>-<random><suffix>" in the target's directory.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target, const std::filesystem::path& suffix) {
    std::random_device device;
    std::uint64_t random = (std::uint64_t(device()) << 32) ^ device();
    std::ostringstream name;
    name << target.filename().string() << ".tmp-" << ::getpid() << '-' << std::hex << random
         << suffix.string();
    return target.parent_path() / name.str();
}

std::string errnoText() { return std::strerror(errno); }

// "<target>: <what> '<temporary>': <the system's reason>".
[[noreturn]] void fail(const std::filesystem::path& target, const std::filesystem::path& temporary,
                       const char* what) {
    std::string reason = errnoText();
    throw Error(target.string() + ": " + what + " '" + temporary.string() + "': " + reason);
}

// "<extension without the dot>:<moment>", the crash points of one write (crash_point.h).
void crashPointOf(const std::filesystem::path& target, std::string_view moment) {
    std::string extension = target.extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    crashPoint(extension + ":" + std::string(moment));
}

// Created with O_EXCL so no other writer shares it, mode 0666 so the umask decides the
// final permissions exactly as for a plainly written file.
int createTemporary(const std::filesystem::path& target, const std::filesystem::path& temporary) {
    int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(target, temporary, "cannot create the temporary file");
    crashPointOf(target, "created");
    return fd;
}

// fsync of a directory makes the rename durable; some file systems refuse it (EINVAL),
// which only means they give no such guarantee.
bool syncDirectory(const std::filesystem::path& directory) {
    std::filesystem::path dir = directory.empty() ? std::filesystem::path(".") : directory;
    int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return false;
    bool ok = ::fsync(fd) == 0 || errno == EINVAL;
    ::close(fd);
    return ok;
}

// The complete temporary (already fsynced) renamed over the target, and the rename made
// durable. Returns once the target is replaced, throws before if it is not.
void renameIntoPlace(const std::filesystem::path& target, const std::filesystem::path& temporary,
                     bool& renamed) {
    if (::rename(temporary.c_str(), target.c_str()) != 0)
        fail(target, temporary, "cannot rename into place the temporary file");
    renamed = true;
    crashPointOf(target, "renamed");
    if (!syncDirectory(target.parent_path()))
        throw Error(target.string() + ": written, but cannot fsync its directory: " + errnoText());
}

// A file written by name may have been replaced rather than rewritten in place, so it is
// reopened by name to be synced.
void syncByName(const std::filesystem::path& target, const std::filesystem::path& temporary) {
    int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail(target, temporary, "cannot reopen the temporary file");
    if (::fsync(fd) != 0) {
        int error = errno;
        ::close(fd);
        errno = error;
        fail(target, temporary, "cannot fsync the temporary file");
    }
    ::close(fd);
}

}  // namespace

AtomicFileWriter::AtomicFileWriter(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporaryPathFor(target_, {})) {
    fd_ = createTemporary(target_, temporary_);
    buffer_.reserve(kBufferBytes);
}

AtomicFileWriter::~AtomicFileWriter() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(temporary_.c_str());
}

void AtomicFileWriter::writeAll(std::span<const std::byte> bytes, std::uint64_t offset) {
    while (!bytes.empty()) {
        ssize_t n = ::pwrite(fd_, bytes.data(), bytes.size(), static_cast<off_t>(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(target_, temporary_, "cannot write the temporary file");
        bytes = bytes.subspan(static_cast<std::size_t>(n));
        offset += static_cast<std::uint64_t>(n);
    }
}

void AtomicFileWriter::flush() {
    writeAll(buffer_, flushedSize_);
    flushedSize_ = size_;
    buffer_.clear();
}

void AtomicFileWriter::append(std::span<const std::byte> bytes) {
    if (buffer_.size() + bytes.size() > kBufferBytes) flush();
    if (bytes.size() >= kBufferBytes) {
        writeAll(bytes, flushedSize_);
        size_ += bytes.size();
        flushedSize_ = size_;
        return;
    }
    buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
    size_ += bytes.size();
}

void AtomicFileWriter::overwrite(std::uint64_t offset, std::span<const std::byte> bytes) {
    if (offset + bytes.size() > size_)
        throw Error(target_.string() + ": internal error: overwrite beyond the bytes written");
    flush();
    writeAll(bytes, offset);
}

void AtomicFileWriter::commit() {
    flush();
    crashPointOf(target_, "written");
    if (::fsync(fd_) != 0) fail(target_, temporary_, "cannot fsync the temporary file");
    int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail(target_, temporary_, "cannot close the temporary file");
    renameIntoPlace(target_, temporary_, committed_);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    try {
        AtomicFileWriter out(path);
        out.append(std::as_bytes(std::span(bytes.data(), bytes.size())));
        out.commit();
    } catch (const Error& e) {
        // "<path>: cannot write file: <what the writer says, without its own path prefix>"
        const std::string prefix = path.string() + ": ";
        std::string what = e.what();
        if (what.starts_with(prefix)) what.erase(0, prefix.size());
        throw Error(prefix + "cannot write file: " + what);
    }
}

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& temporary)>& writeTemporary) {
    const std::filesystem::path temporary = temporaryPathFor(target, target.extension());
    ::close(createTemporary(target, temporary));
    bool renamed = false;
    try {
        try {
            writeTemporary(temporary);
        } catch (const std::exception& e) {
            throw Error(target.string() + ": " + e.what());
        }
        crashPointOf(target, "written");
        syncByName(target, temporary);
        renameIntoPlace(target, temporary, renamed);
    } catch (...) {
        if (!renamed) ::unlink(temporary.c_str());
        throw;
    }
}

}  // namespace opal
