#include "render/image_output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "algebra/error.h"
#include "render/shading.h"

namespace locus::render {

namespace {

void write_channels(const std::string& path, int width, int height, int channels,
                    OIIO::TypeDesc type, const void* data, OIIO::TypeDesc file_type) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) {
        throw Error("cannot write '" + path + "': " + OIIO::geterror());
    }
    OIIO::ImageSpec spec(width, height, channels, file_type);
    if (!out->open(path, spec) || !out->write_image(type, data) || !out->close()) {
        throw Error("cannot write '" + path + "': " + out->geterror());
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
    std::vector<std::string> written;
    if (is_float_format(path)) {
        write_channels(path, image.width, image.height, 3, OIIO::TypeDesc::FLOAT,
                       image.color.data(), OIIO::TypeDesc::HALF);
    } else {
        std::vector<std::uint8_t> srgb(image.color.size());
        std::transform(image.color.begin(), image.color.end(), srgb.begin(),
                       [](float c) { return to_srgb8(c); });
        write_channels(path, image.width, image.height, 3, OIIO::TypeDesc::UINT8, srgb.data(),
                       OIIO::TypeDesc::UINT8);
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
        write_channels(aov_path, image.width, image.height, aov == Aov::normal ? 3 : 1,
                       OIIO::TypeDesc::FLOAT, data.data(), OIIO::TypeDesc::FLOAT);
        written.push_back(aov_path);
    }
    return written;
}

}  // namespace locus::render
