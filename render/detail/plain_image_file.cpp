#include "render/detail/plain_image_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include <spng.h>

namespace locus::render::detail {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

struct SpngFree {
    void operator()(spng_ctx* context) const { spng_ctx_free(context); }
};

// Flushes and closes, reporting a failed write (a full disk shows up at the flush, not at
// fwrite).
std::string close_checked(File file) {
    const int write_errno = std::ferror(file.get()) != 0 ? (errno != 0 ? errno : EIO) : 0;
    if (std::fclose(file.release()) != 0) {
        return std::strerror(errno);
    }
    return write_errno != 0 ? std::strerror(write_errno) : std::string();
}

std::string write_ppm(std::FILE* file, int width, int height, const std::uint8_t* rgb) {
    std::fprintf(file, "P6\n%d %d\n255\n", width, height);
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    if (std::fwrite(rgb, 1, size, file) != size) {
        return std::strerror(errno);
    }
    return {};
}

// The header and the encoding settings every PNG of locus gets, then the pixels; the caller has
// pointed the context at a file or at its own buffer.
int encode_rgb(spng_ctx* context, int width, int height, const std::uint8_t* rgb) {
    spng_ihdr header{};
    header.width = static_cast<std::uint32_t>(width);
    header.height = static_cast<std::uint32_t>(height);
    header.bit_depth = 8;
    header.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
    // zlib level 2 and the Sub filter on every row: on a 512² render (a torus, 786 KB of
    // pixels) 20 ms and 51 KB, where zlib's default level 6 with libspng's adaptive choice of
    // filters per row (libpng's defaults) took 110 ms for 39 KB, a third of the whole command.
    // Rendered pictures are mostly flat background and smooth shading, which Sub predicts.
    int status = spng_set_ihdr(context, &header);
    if (status == 0) {
        status = spng_set_option(context, SPNG_IMG_COMPRESSION_LEVEL, 2);
    }
    if (status == 0) {
        status = spng_set_option(context, SPNG_FILTER_CHOICE, SPNG_FILTER_CHOICE_SUB);
    }
    if (status == 0) {
        const std::size_t size =
            static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
        status = spng_encode_image(context, rgb, size, SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE);
    }
    return status;
}

std::string write_png(std::FILE* file, int width, int height, const std::uint8_t* rgb) {
    std::unique_ptr<spng_ctx, SpngFree> context(spng_ctx_new(SPNG_CTX_ENCODER));
    if (!context) {
        return "cannot create a PNG encoder";
    }
    int status = spng_set_png_file(context.get(), file);
    if (status == 0) {
        status = encode_rgb(context.get(), width, height, rgb);
    }
    if (status != 0) {
        // libspng reports a short write as SPNG_IO_ERROR; errno says why (ENOSPC, EIO, ...).
        return status == SPNG_IO_ERROR && errno != 0 ? std::strerror(errno) : spng_strerror(status);
    }
    return {};
}

}  // namespace

std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

bool is_plain_image_format(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    return extension == ".png" || extension == ".ppm" || extension == ".pnm";
}

std::string write_plain_image(const std::string& path, int width, int height,
                              const std::uint8_t* rgb) {
    errno = 0;
    File file(std::fopen(path.c_str(), "wb"));
    if (!file) {
        return std::strerror(errno);
    }
    const std::string failure = lowercase_extension(path) == ".png"
                                    ? write_png(file.get(), width, height, rgb)
                                    : write_ppm(file.get(), width, height, rgb);
    if (!failure.empty()) {
        return failure;
    }
    return close_checked(std::move(file));
}

std::optional<std::string> encode_png(int width, int height, const std::uint8_t* rgb) {
    std::unique_ptr<spng_ctx, SpngFree> context(spng_ctx_new(SPNG_CTX_ENCODER));
    if (!context || spng_set_option(context.get(), SPNG_ENCODE_TO_BUFFER, 1) != 0 ||
        encode_rgb(context.get(), width, height, rgb) != 0) {
        return std::nullopt;
    }
    std::size_t length = 0;
    int status = 0;
    void* buffer = spng_get_png_buffer(context.get(), &length, &status);
    if (buffer == nullptr || status != 0) {
        return std::nullopt;
    }
    std::string png(static_cast<const char*>(buffer), length);
    std::free(buffer);  // the buffer is the caller's, allocated with malloc
    return png;
}

}  // namespace locus::render::detail
