#include "bench/output_folder.h"

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

}  // namespace opal::bench
