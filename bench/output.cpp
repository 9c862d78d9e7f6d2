#include "bench/output.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace opal::bench {

namespace {

std::filesystem::path temporarySibling(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp.replace_filename(path.stem().string() + ".tmp" + path.extension().string());
    return tmp;
}

}  // namespace

void ensureDirectory(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw std::runtime_error("cannot create output folder '" + dir.string() + "': " +
                                 (ec ? ec.message() : std::string("a file of that name exists")));
}

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<bool(const std::filesystem::path&)>& write) {
    const std::filesystem::path tmp = temporarySibling(path);
    std::string problem;
    try {
        if (!write(tmp)) problem = "write failed";
    } catch (const std::exception& e) {
        problem = e.what();
    }
    std::error_code ec;
    if (problem.empty()) {
        std::filesystem::rename(tmp, path, ec);
        if (!ec) return;
        problem = ec.message();
    }
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("cannot write '" + path.string() + "': " + problem);
}

void writeTextAtomically(const std::filesystem::path& path, std::string_view text) {
    writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(std::strerror(errno));
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        return !out.fail();
    });
}

}  // namespace opal::bench
