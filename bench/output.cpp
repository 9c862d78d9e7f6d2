#include "bench/output.h"

#include "delegate/output/atomic_write.h"
#include "schema/usd/atomic_file.h"

#include <stdexcept>
#include <string>
#include <system_error>

namespace opal::bench {

void ensureDirectory(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw std::runtime_error("cannot create output folder '" + dir.string() + "': " +
                                 (ec ? ec.message() : std::string("a file of that name exists")));
}

// Through the delegate's writer: a unique temporary name, fsync before the rename, and
// on any failure the temporary removed and an error naming the file and the cause.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<bool(const std::filesystem::path&)>& write) {
    try {
        opal::writeAtomically(path, [&](const std::filesystem::path& temporary) {
            if (!write(temporary)) throw std::runtime_error("write failed");
        });
    } catch (const std::exception& e) {
        throw std::runtime_error(e.what());
    }
}

// Through the writer of plain bytes, whose errors carry the system's reason (a full disk,
// a folder without write permission).
void writeTextAtomically(const std::filesystem::path& path, std::string_view text) {
    try {
        opal::writeFileAtomically(path, text);
    } catch (const std::exception& e) {
        throw std::runtime_error(e.what());
    }
}

}  // namespace opal::bench
