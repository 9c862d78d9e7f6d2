// Opal's one way of writing a file so that it is replaced atomically: every byte goes to a
// temporary file `<target>.tmp-<pid>-<random>` in the target's directory (same file
// system), which is fsynced and renamed over the target (then the directory is fsynced).
// Until then the previous target is untouched; if the write fails or is abandoned, the
// temporary file is removed. A crash can leave a stray temporary file but never a
// half-written target. A write passes three crash points (crash_point.h), named for the
// target's extension: "<ext>:created" (empty temporary), "<ext>:written" (complete
// temporary, not yet renamed) and "<ext>:renamed" (in place, directory not yet synced).
// Errors are opal::Error naming the target and the system's reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <filesystem>
#include <functional>
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

// For writers that take a file name (image libraries): calls `writeTemporary` with the
// path of a fresh, empty temporary file next to `target` whose name ends in the target's
// extension (image libraries pick the format by extension), then fsyncs it and renames it
// over `target`. If `writeTemporary` throws, the temporary is removed, `target` is left
// as it was, and opal::Error says "<target>: <what it threw>".
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& temporary)>& writeTemporary);

}  // namespace opal
