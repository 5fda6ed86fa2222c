// Modules of locus: shared objects loaded with dlopen on first use, so that a command that does
// not need their dependencies never loads them (OpenImageIO for EXR and TIFF, cpp-httplib with
// OpenSSL for `locus view`: linked in, each would cost every command its start-up).
#pragma once

#include <string>

namespace locus::render {

// The address of `symbol` in the module `file_name`, loaded once per process. Looked for beside
// an installed executable (PREFIX/bin/locus and PREFIX/lib/locus/`file_name`), in the build tree
// (build/cli/locus and build/`build_subdir`/`file_name`) — both from the executable's own path,
// so that a moved tree still works — and then at `build_path`, where the build put it (for test
// executables elsewhere in the build tree). Throws Error naming `what` and every attempt when
// none loads or the symbol is missing.
void* module_symbol(const std::string& file_name, const std::string& build_subdir,
                    const std::string& build_path, const char* symbol, const std::string& what);

}  // namespace locus::render
