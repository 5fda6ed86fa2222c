#include "cli/version.h"

#include <flint/flint.h>
#include <gmp.h>
#include <zlib.h>

namespace locus::cli {

std::string version_text() {
    return std::string("locus ") + LOCUS_VERSION + "\nFLINT " + FLINT_VERSION + ", GMP " +
           gmp_version + ", OpenImageIO " + LOCUS_OIIO_VERSION + ", zlib " + ZLIB_VERSION;
}

}  // namespace locus::cli
