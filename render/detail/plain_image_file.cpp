#include "render/detail/plain_image_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

#include <tbb/parallel_for.h>

#include "render/large_page_allocator.h"

namespace locus::render::detail {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// Flushes and closes, reporting a failed write (a full disk shows up at the flush, not at
// fwrite).
std::string close_checked(File file) {
    const int write_errno = std::ferror(file.get()) != 0 ? (errno != 0 ? errno : EIO) : 0;
    if (std::fclose(file.release()) != 0) {
        return std::strerror(errno);
    }
    return write_errno != 0 ? std::strerror(write_errno) : std::string();
}

bool write_all(std::FILE* file, const void* data, std::size_t size) {
    return std::fwrite(data, 1, size, file) == size;
}

std::string write_ppm(std::FILE* file, int width, int height, const RgbRowSource& row) {
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(width);
    PixelBuffer<std::uint8_t> rgb(row_bytes * static_cast<std::size_t>(height));
    tbb::parallel_for(0, height, [&](int y) { row(y, rgb.data() + row_bytes * y); });
    const std::string header =
        "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    if (!write_all(file, header.data(), header.size()) ||
        !write_all(file, rgb.data(), rgb.size())) {
        return std::strerror(errno);
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
                              const RgbRowSource& row) {
    errno = 0;
    File file;
    if (lowercase_extension(path) == ".png") {
        // Written as the pieces come. The bands are compressed before the first piece, and the
        // file is opened at it: an encoding that fails (its library missing, memory exhausted)
        // leaves no file.
        std::string failure;
        encode_png(width, height, row, [&](const char* data, std::size_t size) {
            if (!file && failure.empty()) {
                errno = 0;
                file.reset(std::fopen(path.c_str(), "wb"));
                if (!file) {
                    failure = std::strerror(errno);
                }
            }
            if (failure.empty() && !write_all(file.get(), data, size)) {
                failure = std::strerror(errno);
            }
        });
        if (!failure.empty()) {
            return failure;
        }
    } else {
        file.reset(std::fopen(path.c_str(), "wb"));
        if (!file) {
            return std::strerror(errno);
        }
        const std::string failure = write_ppm(file.get(), width, height, row);
        if (!failure.empty()) {
            return failure;
        }
    }
    return close_checked(std::move(file));
}

}  // namespace locus::render::detail
