#include "plugin/shared_library.h"

#include "schema/error.h"

#include <dlfcn.h>

namespace opal {

namespace {

std::string lastDlError() {
    const char* message = dlerror();
    return message ? message : "unknown dynamic loader error";
}

}  // namespace

std::shared_ptr<SharedLibrary> SharedLibrary::open(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw Error(file.string() + ": plugin library not found");
    dlerror();
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw Error(file.string() + ": cannot load plugin library: " + lastDlError());
    return std::shared_ptr<SharedLibrary>(new SharedLibrary(file, handle));
}

SharedLibrary::~SharedLibrary() { dlclose(handle_); }

void* SharedLibrary::symbol(const std::string& name) const {
    dlerror();
    void* address = dlsym(handle_, name.c_str());
    if (!address) throw Error(path_.string() + ": plugin library has no symbol '" + name + "': " + lastDlError());
    return address;
}

}  // namespace opal
