# INTERFACE target carrying the project's warning flags (and sanitizers in the debug preset).
add_library(locus_warnings INTERFACE)
target_compile_options(locus_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast)
if(LOCUS_WERROR)
    target_compile_options(locus_warnings INTERFACE -Werror)
endif()
if(LOCUS_SANITIZE)
    target_compile_options(locus_warnings INTERFACE
        -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    target_link_options(locus_warnings INTERFACE -fsanitize=address,undefined)
endif()
