#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, the tree moved elsewhere: the moved `locus` must
# render a PNG (no module) and an EXR (the OpenImageIO module, found from the executable's own
# path and not from the build tree), serve `locus view` (the HTTP module, found the same way), print its version, and a small program must build against
# the installed headers and CMake package (find_package(locus)) and run.
# Usage: tests/cli/install_test.sh BUILD_DIR [sanitized]   (from the source root, as ctest does;
# `sanitized`: the module is linked in, not installed, under the sanitizers: render/CMakeLists.txt)
set -uo pipefail
build="$1"
sanitized="${2:-}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
locus=""
source "$(dirname "$0")/expect.sh"

expect "cmake --install into a prefix" 0 "" -- cmake --install "$build" --prefix "$tmp/first"
mv "$tmp/first" "$tmp/moved"
locus="$tmp/moved/bin/locus"
sphere="x^2+y^2+z^2-1"
expect "the moved locus renders a PNG" 0 "wrote $tmp/s.png" -- \
    "$locus" render "$sphere" --size 16x16 -o "$tmp/s.png"
# The PNG signature, then IHDR: width 16, height 16, bit depth 8, colour type 2 (RGB).
expect "the PNG is a 16x16 8-bit RGB PNG" 0 "89504e470d0a1a0a0000000d494844520000001000000010 0802" -- \
    bash -c "head -c 26 '$tmp/s.png' | od -An -tx1 | tr -d ' \n' | sed -E 's/(.{48})/\\1 /'"
# glibc's loader names every file it maps: the module must come from the moved tree.
module_loaded="file=$tmp/moved/lib/locus/liblocus_image_file.so"
if [[ "$sanitized" == sanitized ]]; then
    module_loaded="wrote $tmp/s.exr"
fi
expect "the moved locus renders an EXR with its own module" 0 "$module_loaded" -- \
    env LD_DEBUG=files "$locus" render "$sphere" --size 16x16 -o "$tmp/s.exr"
expect "the EXR exists" 0 "" -- test -s "$tmp/s.exr"
# `locus view` loads its HTTP server (cpp-httplib, OpenSSL) as a module, from the moved tree too.
view_loaded="file=$tmp/moved/lib/locus/liblocus_http.so"
if [[ "$sanitized" == sanitized ]]; then
    view_loaded="serving on http://127.0.0.1:"
fi
expect "the moved locus serves with its own HTTP module" 0 "$view_loaded" -- \
    env LD_DEBUG=files "$locus" view "$sphere" --port 0 --timeout 0.5
# Under the sanitizers the HTTP module is linked in (view/CMakeLists.txt says why).
if [[ "$sanitized" != sanitized ]]; then
    expect "locus itself needs neither cpp-httplib nor OpenSSL" 1 "" -- \
        bash -c "ldd '$locus' | grep -E 'libcpp-httplib|libssl|libcrypto'"
fi
expect "--version names the libraries" 0 "FLINT " -- "$locus" --version
expect "docs and examples are installed" 0 "" -- \
    test -s "$tmp/moved/share/doc/locus/user-guide.md" -a -s "$tmp/moved/share/locus/scenes/twisted_torus.toml" \
    -a -s "$tmp/moved/share/locus/examples/enneper.param"

# The Python package, where the build has it (not under the sanitizers): importable from the
# moved tree's dist-packages.
extension=$(find "$tmp/moved/lib" -name '_locus*.so' -print -quit)
if [[ -n "$extension" ]]; then
    site=$(dirname "$(dirname "$extension")")
    expect "the moved Python package computes a basis" 0 "y^2-1" -- \
        env PYTHONPATH="$site" /usr/bin/python3 -c \
        "import locus; print(locus.groebner(['x^2+y','y^2-1'], vars='x,y', order='lex'))"
fi

mkdir -p "$tmp/consumer"
cat > "$tmp/consumer/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(consumer LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(locus 0.1 REQUIRED)
add_executable(consumer main.cpp)
target_link_libraries(consumer PRIVATE locus::algebra)
CMAKE
cat > "$tmp/consumer/main.cpp" <<'CPP'
#include <iostream>

#include "algebra/parse.h"
#include "algebra/print.h"

int main() {
    const locus::algebra::IdealFile ideal = locus::algebra::parse_ideal_file("vars: x,y\n(x+y)^2\n");
    std::cout << locus::algebra::to_string(ideal.generators.front()) << "\n";
}
CPP
expect "find_package(locus) configures" 0 "" -- \
    cmake -S "$tmp/consumer" -B "$tmp/consumer/build" -DCMAKE_PREFIX_PATH="$tmp/moved"
expect "the consumer builds against the installed headers" 0 "" -- \
    cmake --build "$tmp/consumer/build" -j 1
expect "the consumer runs" 0 "x^2+2*x*y+y^2" -- "$tmp/consumer/build/consumer"

summary
