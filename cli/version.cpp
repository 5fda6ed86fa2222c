#include "cli/version.h"

#include <flint/flint.h>
#include <gmp.h>
#include <isa-l.h>
#include <zlib.h>

#include <string>

namespace locus::cli {

std::string version_text() {
    return std::string("locus ") + LOCUS_VERSION + "\nFLINT " + FLINT_VERSION + ", GMP " +
           gmp_version + ", OpenImageIO " + LOCUS_OIIO_VERSION + ", ISA-L " +
           std::to_string(ISAL_MAJOR_VERSION) + "." + std::to_string(ISAL_MINOR_VERSION) + "." +
           std::to_string(ISAL_PATCH_VERSION) + ", zlib " + ZLIB_VERSION;
}

}  // namespace locus::cli
