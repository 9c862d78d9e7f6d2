// Writing a file so that it is replaced atomically: every byte goes to a temporary file
// `<target>.tmp-<pid>-<random>` in the target's directory, which commit() fsyncs and
// renames over the target (then fsyncs the directory). Until then the previous target is
// untouched; if the writer is destroyed without commit() (an exception, a failed
// producer), the temporary file is removed. A crash can leave a stray temporary file but
// never a half-written target. A write passes three crash points (crash_point.h), named
// for the target's extension: "<ext>:created" (empty temporary), "<ext>:written" (complete
// temporary, not yet renamed) and "<ext>:renamed" (in place, directory not yet synced).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <filesystem>
#include <span>
#include <vector>

namespace opal {

class AtomicFileWriter {
public:
    // Creates the temporary file. Throws opal::Error naming the target on failure.
    explicit AtomicFileWriter(std::filesystem::path target);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    // Appends at the end (buffered).
    void append(std::span<const std::byte> bytes);
    // Overwrites bytes already appended, e.g. a header whose fields are known last.
    void overwrite(std::uint64_t offset, std::span<const std::byte> bytes);
    std::uint64_t size() const { return size_; }

    // Flushes, fsyncs, closes, renames over the target and fsyncs the directory.
    void commit();

    const std::filesystem::path& target() const { return target_; }
    const std::filesystem::path& temporary() const { return temporary_; }

private:
    void flush();
    void writeAll(std::span<const std::byte> bytes, std::uint64_t offset);
    [[noreturn]] void fail(const char* what) const;  // what + strerror(errno)

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    int fd_ = -1;
    bool committed_ = false;
    std::uint64_t size_ = 0;        // bytes appended so far
    std::uint64_t flushedSize_ = 0;  // bytes of those already in the file
    std::vector<std::byte> buffer_;
};

// The whole of `bytes` as the new content of `path`, through an AtomicFileWriter.
// Throws opal::Error naming `path` and the system error.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace opal
