// The files farm tasks hand each other (bake/farm/farm_stage.h): a header, then sections
// of bytes, each with its own XXH64, so that a task reads and checks just the sections it
// needs (a columns task one column block of every rows shard):
//   "OPALTASK" | u32 format version | u32 section count |
//   per section: u64 byte size, u64 XXH64 of its bytes | u64 XXH64 of the header so far |
//   the sections' bytes, one after the other.
// Written atomically (schema/usd/atomic_file.h): a task killed while writing leaves no
// file, never a partial one. Nothing in the file depends on when or where it was written,
// so a task run again writes the same bytes. Every error names the file (and the section).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace opal {

class AtomicFileWriter;
class MappedFile;

// The bytes of one section, built field by field (little-endian).
class SectionWriter {
public:
    void u32(std::uint32_t v) { put(v); }
    void u64(std::uint64_t v) { put(v); }
    void f64(double v) { put(v); }
    void text(std::string_view s);  // u64 length, then the bytes
    template <class T>
    void array(std::span<const T> values) {  // u64 count, then the values
        static_assert(std::is_standard_layout_v<T>);  // numbers, or plain structs of them (V3f)
        u64(values.size());
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
    }
    template <class T>
    void array(const std::vector<T>& values) {
        array(std::span<const T>(values));
    }
    // One number without a count: for an array written element by element after its
    // count (u64), when the values are not in one span.
    template <class T>
    void element(T v) {
        static_assert(std::is_arithmetic_v<T>);
        put(v);
    }
    // Room for `bytes` in all: a section written into exactly the memory it needs.
    void reserve(std::size_t bytes) { bytes_.reserve(bytes); }
    std::string take() { return std::move(bytes_); }

private:
    template <class T>
    void put(T v) {
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    std::string bytes_;
};

// The values of an array in a section, read in place (each through memcpy: the bytes
// need not be aligned for T), for arrays too large to copy out.
template <class T>
class SectionArray {
public:
    SectionArray() = default;
    SectionArray(const char* data, std::size_t count) : data_(data), count_(count) {}
    std::size_t size() const { return count_; }
    T operator[](std::size_t i) const {
        T v;
        std::memcpy(&v, data_ + i * sizeof(T), sizeof v);
        return v;
    }

private:
    const char* data_ = nullptr;
    std::size_t count_ = 0;
};

// Reads one section's fields in the order they were written; running off its end or an
// array longer than what is left throws opal::Error naming `context` and the field.
class SectionReader {
public:
    // Reads `bytes`, which `file` keeps alive (the task file's mapping).
    SectionReader(std::shared_ptr<const MappedFile> file, std::string_view bytes, std::string context)
        : file_(std::move(file)), bytes_(bytes), context_(std::move(context)) {}
    std::uint32_t u32(std::string_view what) { return get<std::uint32_t>(what); }
    std::uint64_t u64(std::string_view what) { return get<std::uint64_t>(what); }
    double f64(std::string_view what) { return get<double>(what); }
    std::string text(std::string_view what);
    template <class T>
    std::vector<T> array(std::string_view what) {
        const std::uint64_t count = u64(what);
        if (count > (bytes_.size() - at_) / sizeof(T)) fail(what, "holds " + std::to_string(count) + " values");
        std::vector<T> values(count);
        std::memcpy(static_cast<void*>(values.data()), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return values;
    }
    // The next array in place: valid while this reader, or the TaskFile it came from, lives.
    template <class T>
    SectionArray<T> view(std::string_view what) {
        static_assert(std::is_arithmetic_v<T>);
        const std::uint64_t count = u64(what);
        if (count > (bytes_.size() - at_) / sizeof(T)) fail(what, "holds " + std::to_string(count) + " values");
        const SectionArray<T> values(bytes_.data() + at_, count);
        at_ += count * sizeof(T);
        return values;
    }
    // Throws unless every byte was read.
    void expectEnd() const;
    [[noreturn]] void fail(std::string_view what, const std::string& problem) const;
    const std::string& context() const { return context_; }

private:
    template <class T>
    T get(std::string_view what) {
        if (bytes_.size() - at_ < sizeof(T)) fail(what, "is cut short");
        T v;
        std::memcpy(&v, bytes_.data() + at_, sizeof v);
        at_ += sizeof v;
        return v;
    }
    std::shared_ptr<const MappedFile> file_;
    std::string_view bytes_;
    std::string context_;
    std::size_t at_ = 0;
};

// Writes a task file section by section, so that a task holds one section at a time: the
// header is written last, over its place at the start. Nothing is at `path` until commit().
class TaskFileWriter {
public:
    TaskFileWriter(const std::filesystem::path& path, std::size_t sectionCount);
    ~TaskFileWriter();
    TaskFileWriter(const TaskFileWriter&) = delete;
    TaskFileWriter& operator=(const TaskFileWriter&) = delete;

    void add(const std::string& section);
    // Throws unless exactly sectionCount sections were added.
    void commit();

private:
    std::unique_ptr<AtomicFileWriter> file_;
    std::size_t expected_;
    std::vector<std::uint64_t> sizes_, checksums_;
};

// Writes `sections` as a task file at `path`, atomically.
void writeTaskFile(const std::filesystem::path& path, std::span<const std::string> sections);

// A task file mapped into memory (mapped_file.h): sections are read in place.
class TaskFile {
public:
    // Maps the file and checks its header. Throws opal::Error naming the file.
    explicit TaskFile(std::filesystem::path path);

    std::size_t sections() const { return sections_.size(); }
    // Section i, its XXH64 checked; its bytes stay mapped while the reader lives.
    SectionReader section(std::size_t i) const;
    // Reads and checks every section.
    void verify() const;
    const std::filesystem::path& path() const { return path_; }

private:
    struct Section {
        std::uint64_t offset, size, checksum;
    };
    std::filesystem::path path_;
    std::shared_ptr<const MappedFile> file_;
    std::vector<Section> sections_;
};

// True when `path` exists and is a whole task file whose every checksum holds.
bool isCompleteTaskFile(const std::filesystem::path& path);

}  // namespace opal
