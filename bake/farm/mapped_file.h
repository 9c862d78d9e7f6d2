// A whole file mapped read-only into memory (POSIX mmap), for the farm's task files: a
// task reads its sections from the page cache in place, with no buffer to zero and no
// copy (a columns task read its share of every rows file through std::ifstream into
// zero-filled strings; two thirds of its time went to that memset, its page faults and
// the copy). Task files are only ever replaced by rename (atomic_file.h), never changed
// in place, so the mapped bytes stay the ones opened.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace opal {

class MappedFile {
public:
    // Maps the whole file. Throws opal::Error naming the file and the system's reason.
    explicit MappedFile(const std::filesystem::path& path);
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    std::string_view bytes() const { return {data_, size_}; }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    const char* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace opal
