# Dependencies, all from Debian packages (scripts/install-deps installs them).
find_package(PkgConfig REQUIRED)
# FLINT 2.9 ships flint.pc only in some builds; fall back to a plain library search.
pkg_check_modules(FLINT IMPORTED_TARGET flint)
if(NOT FLINT_FOUND)
    find_path(FLINT_INCLUDE_DIR flint/flint.h REQUIRED)
    find_library(FLINT_LIBRARY flint REQUIRED)
    add_library(locus_flint INTERFACE)
    target_include_directories(locus_flint SYSTEM INTERFACE ${FLINT_INCLUDE_DIR})
    target_link_libraries(locus_flint INTERFACE ${FLINT_LIBRARY})
else()
    add_library(locus_flint INTERFACE)
    target_link_libraries(locus_flint INTERFACE PkgConfig::FLINT)
endif()
pkg_check_modules(GMP REQUIRED IMPORTED_TARGET gmp)
target_link_libraries(locus_flint INTERFACE PkgConfig::GMP)
find_package(CLI11 CONFIG REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(glm CONFIG REQUIRED)
find_package(TBB CONFIG REQUIRED)
# Debian's OpenImageIOConfig.cmake names /usr/include/opencv4 even without OpenCV installed,
# which CMake rejects; the pkg-config file is accurate.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
find_package(tomlplusplus CONFIG REQUIRED)
# The web server of `locus view` (view/).
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
# PNG without OpenImageIO (render/detail/png_encoder.cpp): ISA-L's igzip deflates (its headers
# here; the library is loaded with dlopen on the first PNG), zlib gives the checksums.
pkg_check_modules(ISAL REQUIRED libisal)
find_package(ZLIB REQUIRED)
if(LOCUS_BUILD_TESTS)
    # A PNG decoder that shares no code with the encoder (tests/render/png_encoder_test.cpp).
    pkg_check_modules(SPNG REQUIRED IMPORTED_TARGET spng)
endif()
if(LOCUS_BUILD_TESTS)
    find_package(GTest REQUIRED)
    include(GoogleTest)
endif()

# locus_add_test(<name> SOURCES ... LIBS ...): one GoogleTest executable, each test visible to ctest.
function(locus_add_test name)
    cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main locus_warnings)
    target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
    gtest_discover_tests(${name}
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
        PROPERTIES ENVIRONMENT "LOCUS_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
        DISCOVERY_TIMEOUT 60)
endfunction()
