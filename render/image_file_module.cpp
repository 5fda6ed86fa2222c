// The OpenImageIO side of image output, built as a module that render/image_output.cpp loads
// with dlopen on first use. Linking OpenImageIO into the executable costs 0.3 s at every start
// on Debian 12 (its dependencies — OpenCV video I/O, GDAL, FFmpeg, OpenVDB — run their
// initialisers), which every `locus groebner` or `locus trace` call would pay; loading it only
// when an image is written keeps those commands instant.
#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>
#include <string>

namespace {
void set_error(char* error, std::size_t size, const std::string& message) {
    std::strncpy(error, message.c_str(), size - 1);
    error[size - 1] = '\0';
}
}  // namespace

// Writes `channels` interleaved channels of width×height pixels. `data_is_float`: data holds
// floats (written as `file_is_half` ? half : float), else bytes (written as bytes). Returns 0 on
// success, otherwise 1 with a message in `error`.
extern "C" int locus_write_image_file(const char* path, int width, int height, int channels,
                                      const void* data, int data_is_float, int file_is_half,
                                      char* error, std::size_t error_size) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) {
        set_error(error, error_size, OIIO::geterror());
        return 1;
    }
    const OIIO::TypeDesc data_type = data_is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    const OIIO::TypeDesc file_type = !data_is_float ? OIIO::TypeDesc::UINT8
                                     : file_is_half ? OIIO::TypeDesc::HALF
                                                    : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(width, height, channels, file_type);
    if (!out->open(path, spec) || !out->write_image(data_type, data) || !out->close()) {
        set_error(error, error_size, out->geterror());
        return 1;
    }
    return 0;
}
