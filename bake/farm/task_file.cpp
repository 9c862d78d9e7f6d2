#include "bake/farm/task_file.h"

#include "bake/farm/mapped_file.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <algorithm>

namespace opal {

namespace {

constexpr std::string_view kMagic = "OPALTASK";
// 2: the environment error in the options and the asset; 3: columns files hold the
// histogram alone; 4: rows sections count entries per row instead of naming each one's row
constexpr std::uint32_t kVersion = 4;
constexpr std::uint32_t kMaxSections = 1u << 20;

std::uint64_t checksum(std::string_view bytes) { return xxh64(std::as_bytes(std::span(bytes.data(), bytes.size()))); }

template <class T>
void append(std::string& out, T v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

void SectionWriter::text(std::string_view s) {
    u64(s.size());
    bytes_.append(s);
}

std::string SectionReader::text(std::string_view what) {
    const std::uint64_t size = u64(what);
    if (size > bytes_.size() - at_) fail(what, "holds " + std::to_string(size) + " bytes");
    std::string s(bytes_.substr(at_, size));
    at_ += size;
    return s;
}

void SectionReader::expectEnd() const {
    if (at_ != bytes_.size())
        throw Error(context_ + ": " + std::to_string(bytes_.size() - at_) + " bytes after the last field");
}

void SectionReader::fail(std::string_view what, const std::string& problem) const {
    throw Error(context_ + ": at byte " + std::to_string(at_) + ": " + std::string(what) + " " + problem +
                ", past the section's " + std::to_string(bytes_.size()) + " bytes");
}

namespace {

std::string header(std::span<const std::uint64_t> sizes, std::span<const std::uint64_t> checksums) {
    std::string h(kMagic);
    append(h, kVersion);
    append(h, std::uint32_t(sizes.size()));
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        append(h, sizes[i]);
        append(h, checksums[i]);
    }
    append(h, checksum(h));
    return h;
}

std::span<const std::byte> bytesOf(const std::string& s) { return std::as_bytes(std::span(s.data(), s.size())); }

}  // namespace

TaskFileWriter::TaskFileWriter(const std::filesystem::path& path, std::size_t sectionCount)
    : file_(std::make_unique<AtomicFileWriter>(path)), expected_(sectionCount) {
    if (sectionCount > kMaxSections)
        throw Error(path.string() + ": " + std::to_string(sectionCount) + " sections, at most " +
                    std::to_string(kMaxSections));
    const std::vector<std::uint64_t> zeros(sectionCount, 0);
    file_->append(bytesOf(header(zeros, zeros)));  // the place of the header
}

TaskFileWriter::~TaskFileWriter() = default;

void TaskFileWriter::add(const std::string& section) {
    if (sizes_.size() == expected_)
        throw Error(file_->target().string() + ": more than the " + std::to_string(expected_) + " sections announced");
    file_->append(bytesOf(section));
    sizes_.push_back(section.size());
    checksums_.push_back(checksum(section));
}

void TaskFileWriter::commit() {
    if (sizes_.size() != expected_)
        throw Error(file_->target().string() + ": " + std::to_string(sizes_.size()) + " sections of the " +
                    std::to_string(expected_) + " announced");
    file_->overwrite(0, bytesOf(header(sizes_, checksums_)));
    file_->commit();
}

void writeTaskFile(const std::filesystem::path& path, std::span<const std::string> sections) {
    TaskFileWriter file(path, sections.size());
    for (const std::string& s : sections) file.add(s);
    file.commit();
}


TaskFile::TaskFile(std::filesystem::path path) : path_(std::move(path)) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path_, error))
        throw Error(path_.string() + ": cannot read the farm task file: " +
                    (error ? error.message() : std::string("not a regular file")));
    file_ = std::make_shared<const MappedFile>(path_);
    const std::string_view bytes = file_->bytes();
    const std::uint64_t fileSize = bytes.size();
    const std::size_t fixed = kMagic.size() + 2 * sizeof(std::uint32_t);
    if (bytes.size() < fixed || bytes.compare(0, kMagic.size(), kMagic) != 0)
        throw Error(path_.string() + ": not a farm task file (no OPALTASK header)");
    std::uint32_t version = 0, count = 0;
    std::memcpy(&version, bytes.data() + kMagic.size(), sizeof version);
    std::memcpy(&count, bytes.data() + kMagic.size() + sizeof version, sizeof count);
    if (version != kVersion)
        throw Error(path_.string() + ": farm task file version " + std::to_string(version) + ", this opal-bake reads " +
                    std::to_string(kVersion));
    if (count > kMaxSections) throw Error(path_.string() + ": " + std::to_string(count) + " sections (corrupt header)");
    const std::uint64_t headerSize = fixed + std::uint64_t(count) * 16 + 8;
    if (headerSize > fileSize)
        throw Error(path_.string() + ": the header is cut short (the file has " + std::to_string(fileSize) + " bytes)");
    const std::string_view header = bytes.substr(0, headerSize);
    std::uint64_t stored = 0;
    std::memcpy(&stored, header.data() + headerSize - 8, sizeof stored);
    if (stored != checksum(header.substr(0, headerSize - 8)))
        throw Error(path_.string() + ": the header's checksum does not match (a damaged farm task file)");
    std::uint64_t offset = headerSize;
    for (std::uint32_t i = 0; i < count; ++i) {
        Section s{offset, 0, 0};
        std::memcpy(&s.size, header.data() + fixed + 16 * i, 8);
        std::memcpy(&s.checksum, header.data() + fixed + 16 * i + 8, 8);
        if (s.size > fileSize - std::min(offset, fileSize))
            throw Error(path_.string() + ": section " + std::to_string(i) + " of " + std::to_string(s.size) +
                        " bytes runs past the end of the file (" + std::to_string(fileSize) + " bytes)");
        offset += s.size;
        sections_.push_back(s);
    }
    if (offset != fileSize)
        throw Error(path_.string() + ": " + std::to_string(fileSize) + " bytes, the header describes " +
                    std::to_string(offset));
}

SectionReader TaskFile::section(std::size_t i) const {
    const std::string context = path_.string() + ": section " + std::to_string(i);
    if (i >= sections_.size())
        throw Error(context + ": the file has " + std::to_string(sections_.size()) + " sections");
    const Section& s = sections_[i];
    const std::string_view bytes = file_->bytes().substr(s.offset, s.size);
    if (checksum(bytes) != s.checksum)
        throw Error(context + ": checksum mismatch (a damaged farm task file; run the task again)");
    return SectionReader(file_, bytes, context);
}

void TaskFile::verify() const {
    for (std::size_t i = 0; i < sections_.size(); ++i) (void)section(i);
}

bool isCompleteTaskFile(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return false;
    try {
        TaskFile(path).verify();
        return true;
    } catch (const Error&) {
        return false;
    }
}

}  // namespace opal
