#include "render/loadable_module.h"

#include <filesystem>
#include <vector>

#include <dlfcn.h>

#include "algebra/error.h"

namespace locus::render {

namespace {

std::vector<std::string> candidates(const std::string& file_name, const std::string& build_subdir,
                                    const std::string& build_path) {
    std::vector<std::string> out;
    std::error_code failure;
    const std::filesystem::path executable =
        std::filesystem::read_symlink("/proc/self/exe", failure);
    if (!failure) {
        const std::filesystem::path prefix = executable.parent_path().parent_path();
        out.push_back((prefix / "lib" / "locus" / file_name).string());
        out.push_back((prefix / build_subdir / file_name).string());
    }
    out.push_back(build_path);
    return out;
}

}  // namespace

void* module_symbol(const std::string& file_name, const std::string& build_subdir,
                    const std::string& build_path, const char* symbol, const std::string& what) {
    std::string errors;
    for (const std::string& candidate : candidates(file_name, build_subdir, build_path)) {
        // dlopen counts references: a module loaded before is found again, not loaded twice.
        if (void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL)) {
            if (void* address = dlsym(module, symbol)) {
                return address;
            }
            throw Error("the " + what + " module " + candidate + " lacks " + symbol);
        }
        errors += std::string("\n  ") + dlerror();
    }
    throw Error("cannot load the " + what + " module:" + errors);
}

}  // namespace locus::render
