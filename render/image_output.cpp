#include "render/image_output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <dlfcn.h>

#include "algebra/error.h"
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
    static const WriteFunction writer = [] {
        void* module = dlopen(LOCUS_IMAGE_MODULE, RTLD_NOW | RTLD_LOCAL);
        if (module == nullptr) {
            module = dlopen("liblocus_image_file.so", RTLD_NOW | RTLD_LOCAL);
        }
        if (module == nullptr) {
            throw Error(std::string("cannot load the image writer module: ") + dlerror());
        }
        return reinterpret_cast<WriteFunction>(dlsym(module, "locus_write_image_file"));
    }();
    if (writer == nullptr) {
        throw Error("the image writer module lacks locus_write_image_file");
    }
    return writer;
}
#endif

void write_channels(const std::string& path, int width, int height, int channels, const void* data,
                    bool data_is_float, bool file_is_half) {
    char error[512] = "";
    if (image_writer()(path.c_str(), width, height, channels, data, data_is_float ? 1 : 0,
                       file_is_half ? 1 : 0, error, sizeof error) != 0) {
        throw Error("cannot write '" + path + "': " + error);
    }
}

bool is_float_format(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".exr" || extension == ".hdr";
}

}  // namespace

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
    } else {
        std::vector<std::uint8_t> srgb(image.color.size());
        std::transform(image.color.begin(), image.color.end(), srgb.begin(),
                       [](float c) { return to_srgb8(c); });
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

}  // namespace locus::render
