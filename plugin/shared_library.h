// A shared library opened with dlopen(RTLD_NOW | RTLD_LOCAL) and closed when the last
// owner lets go. Objects whose code lives in the library hold a shared_ptr to it, so it
// is never unloaded under them.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace opal {

class SharedLibrary {
public:
    // Throws opal::Error naming the file: missing, or dlopen's own message (not an ELF
    // file, an unresolved symbol, a missing dependency, ...).
    static std::shared_ptr<SharedLibrary> open(const std::filesystem::path& file);

    ~SharedLibrary();
    SharedLibrary(const SharedLibrary&) = delete;
    SharedLibrary& operator=(const SharedLibrary&) = delete;

    const std::filesystem::path& path() const { return path_; }

    // The address of the exported `name`; throws opal::Error with dlerror's text if the
    // library does not export it.
    void* symbol(const std::string& name) const;

private:
    SharedLibrary(std::filesystem::path path, void* handle) : path_(std::move(path)), handle_(handle) {}

    std::filesystem::path path_;
    void* handle_;
};

}  // namespace opal
