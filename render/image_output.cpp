#include "render/image_output.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>

#include <unistd.h>  // for access

#include <tbb/parallel_for.h>

#include "algebra/error.h"
#include "render/detail/plain_image_file.h"
#include "render/detail/png_encoder.h"
#include "render/loadable_module.h"
#include "render/shading.h"

#ifdef LOCUS_IMAGE_LINKED
// Sanitizer builds link the image writer in (render/CMakeLists.txt says why).
extern "C" int locus_write_image_file(const char* path, int width, int height, int channels,
                                      const void* data, int data_is_float, int file_is_half,
                                      char* error, std::size_t error_size);
#endif

namespace locus::render {

namespace {

using WriteFunction = int (*)(const char*, int, int, int, const void*, int, int, char*,
                              std::size_t);

#ifdef LOCUS_IMAGE_LINKED
WriteFunction image_writer() {
    return &locus_write_image_file;
}
#else
// The OpenImageIO module (render/image_file_module.cpp), loaded once on first use.
WriteFunction image_writer() {
    static const WriteFunction writer = reinterpret_cast<WriteFunction>(module_symbol(
        "liblocus_image_file.so", "render", LOCUS_IMAGE_MODULE, "locus_write_image_file",
        "image writer (needed for every format but 8-bit PNG and PPM)"));
    return writer;
}
#endif

// The 8-bit sRGB codes of the colours of row y.
void srgb8_row(const RenderedImage& image, int y, std::uint8_t* rgb) {
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(image.width);
    to_srgb8(image.color.data() + row_bytes * static_cast<std::size_t>(y), rgb, row_bytes);
}

// The 8-bit sRGB codes of the whole image, for the formats OpenImageIO writes, rows side by
// side: on one thread after the frame the conversion was 2–3 % of a 512² low-degree render's
// CPU time, all of it on the whole command's critical path. (`locus render --threads N` bounds
// this too: the command caps TBB's parallelism for all its phases.) PNG and PPM convert row by
// row as they encode.
PixelBuffer<std::uint8_t> srgb8_of(const RenderedImage& image) {
    PixelBuffer<std::uint8_t> srgb(image.color.size());
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(image.width);
    tbb::parallel_for(0, image.height,
                      [&](int y) { srgb8_row(image, y, srgb.data() + row_bytes * y); });
    return srgb;
}

// Writes `path` through `write`, which writes the file named by its argument and returns what
// went wrong ("" on success). Written under partial_path(path) and renamed when complete, so
// that a failure (a full disk, a timeout) never leaves a truncated image under the name asked
// for.
template <class Write>
void write_through_partial(const std::string& path, const Write& write) {
    const std::string partial = partial_path(path);
    const std::string failure_message = write(partial);
    if (!failure_message.empty()) {
        std::remove(partial.c_str());
        throw ResourceLimit("cannot write '" + path + "': " + failure_message);
    }
    std::error_code failure;
    std::filesystem::rename(partial, path, failure);
    if (failure) {
        std::remove(partial.c_str());
        throw ResourceLimit("cannot write '" + path + "': " + failure.message());
    }
}

// Every format but 8-bit PNG and PPM, and every float image, through the OpenImageIO module:
// the common case never pays for loading it.
void write_channels(const std::string& path, int width, int height, int channels, const void* data,
                    bool data_is_float, bool file_is_half) {
    write_through_partial(path, [&](const std::string& partial) {
        char error[512] = "";
        return image_writer()(partial.c_str(), width, height, channels, data, data_is_float ? 1 : 0,
                              file_is_half ? 1 : 0, error, sizeof error) != 0
                   ? std::string(error)
                   : std::string();
    });
}

bool is_float_format(const std::string& path) {
    const std::string extension = detail::lowercase_extension(path);
    return extension == ".exr" || extension == ".hdr";
}

}  // namespace

std::string partial_path(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / (".locus-partial." + p.filename().string())).string();
}

void check_image_path(const std::string& path) {
    const std::string extension = detail::lowercase_extension(path);
    static const char* const known[] = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr",
                                        ".hdr", ".ppm", ".pnm",  ".bmp", ".tga",  ".webp"};
    if (std::find(std::begin(known), std::end(known), extension) == std::end(known)) {
        throw InputError("output '" + path + "'",
                         extension.empty()
                             ? "no extension to name the image format (.png, .exr, .tif, ...)"
                             : "unknown image format '" + extension +
                                   "'; expected .png, .jpg, .tif, .exr, .hdr, .ppm, .bmp, "
                                   ".tga or .webp");
    }
    const std::filesystem::path directory = std::filesystem::path(path).has_parent_path()
                                                ? std::filesystem::path(path).parent_path()
                                                : std::filesystem::path(".");
    std::error_code failure;
    if (!std::filesystem::is_directory(directory, failure)) {
        throw InputError("output '" + path + "'",
                         "the folder '" + directory.string() + "' does not exist");
    }
    if (access(directory.c_str(), W_OK) != 0) {
        throw InputError("output '" + path + "'",
                         "the folder '" + directory.string() + "' is not writable");
    }
    if (std::filesystem::is_directory(path, failure)) {
        throw InputError("output '" + path + "'", "is a folder");
    }
}

Aov parse_aov(const std::string& name) {
    if (name == "depth") {
        return Aov::depth;
    }
    if (name == "normal") {
        return Aov::normal;
    }
    if (name == "work") {
        return Aov::work;
    }
    throw InputError("aov '" + name + "'", "unknown output; expected depth, normal or work");
}

void prepare_image_writer(const std::string& path) {
    if (detail::lowercase_extension(path) == ".png") {
        detail::prepare_png_encoder();
    }
}

std::vector<std::string> write_image(const RenderedImage& image, const std::string& path,
                                     const std::vector<Aov>& aovs) {
    if (!aovs.empty() && image.depth.empty()) {
        throw Error(
            "write_image: AOVs asked for an image rendered without them "
            "(ExecutionSettings::aovs)");
    }
    std::vector<std::string> written;
    if (is_float_format(path)) {
        write_channels(path, image.width, image.height, 3, image.color.data(), true, true);
    } else if (detail::is_plain_image_format(path)) {
        write_through_partial(path, [&](const std::string& partial) {
            return detail::write_plain_image(
                partial, image.width, image.height,
                [&](int y, std::uint8_t* rgb) { srgb8_row(image, y, rgb); });
        });
    } else {
        const PixelBuffer<std::uint8_t> srgb = srgb8_of(image);
        write_channels(path, image.width, image.height, 3, srgb.data(), false, false);
    }
    written.push_back(path);
    const std::filesystem::path base(path);
    for (Aov aov : aovs) {
        const char* name = aov == Aov::depth ? "depth" : aov == Aov::normal ? "normal" : "work";
        const std::string aov_path =
            (base.parent_path() / (base.stem().string() + "." + name + ".exr")).string();
        const std::vector<float>& data = aov == Aov::depth    ? image.depth
                                         : aov == Aov::normal ? image.normal
                                                              : image.work;
        write_channels(aov_path, image.width, image.height, aov == Aov::normal ? 3 : 1, data.data(),
                       true, false);
        written.push_back(aov_path);
    }
    return written;
}

std::string png_bytes(const RenderedImage& image) {
    return detail::encode_png(image.width, image.height,
                              [&](int y, std::uint8_t* rgb) { srgb8_row(image, y, rgb); });
}

}  // namespace locus::render
