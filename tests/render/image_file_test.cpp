// The colour image written without OpenImageIO (PNG by render/detail/png_encoder, PPM) must read
// back, through OpenImageIO, as exactly the 8-bit sRGB pixels the renderer produced; failed
// writes must be reported and leave nothing under the name asked for.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "algebra/error.h"
#include "render/detail/plain_image_file.h"
#include "render/image_output.h"
#include "render/shading.h"

namespace locus::render {
namespace {

// Deterministic colours over the whole 0..1 range (and past it: the writer clamps).
RenderedImage gradient_image(int width, int height) {
    RenderedImage image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.color.push_back(static_cast<float>(x) / static_cast<float>(width - 1));
            image.color.push_back(static_cast<float>(y) / static_cast<float>(height - 1));
            image.color.push_back(static_cast<float>((x * 7 + y * 13) % 17) / 15.0f - 0.05f);
        }
    }
    return image;
}

std::vector<std::uint8_t> expected_srgb(const RenderedImage& image) {
    std::vector<std::uint8_t> bytes;
    for (float c : image.color) {
        bytes.push_back(to_srgb8(c));
    }
    return bytes;
}

std::filesystem::path scratch(const std::string& name) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() /
        ("locus-image-file-test-" +
         std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(folder);
    return folder / name;
}

TEST(ImageFile, PngReadsBackAsTheRenderedPixels) {
    // Odd sizes, so that no row padding hides; 23 rows are one band of the encoder, 230 several.
    for (const int height : {23, 230}) {
        const RenderedImage image = gradient_image(37, height);
        const std::filesystem::path path = scratch("gradient.png");
        write_image(image, path.string());
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
        ASSERT_TRUE(in) << OIIO::geterror();
        const OIIO::ImageSpec& spec = in->spec();
        EXPECT_EQ(spec.width, 37);
        EXPECT_EQ(spec.height, height);
        EXPECT_EQ(spec.nchannels, 3);
        EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
        std::vector<std::uint8_t> pixels(37 * static_cast<std::size_t>(height) * 3);
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
        EXPECT_EQ(pixels, expected_srgb(image)) << height;
        EXPECT_FALSE(std::filesystem::exists(partial_path(path.string())));
    }
}

TEST(ImageFile, PpmIsBinaryP6WithTheRenderedPixels) {
    const RenderedImage image = gradient_image(5, 4);
    const std::filesystem::path path = scratch("gradient.PPM");  // the extension in any case
    write_image(image, path.string());
    std::ifstream file(path, std::ios::binary);
    std::string magic;
    int width = 0;
    int height = 0;
    int max_value = 0;
    file >> magic >> width >> height >> max_value;
    file.get();  // the single whitespace byte before the raster
    EXPECT_EQ(magic, "P6");
    EXPECT_EQ(width, 5);
    EXPECT_EQ(height, 4);
    EXPECT_EQ(max_value, 255);
    std::vector<std::uint8_t> pixels(5 * 4 * 3);
    file.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
    EXPECT_EQ(file.gcount(), static_cast<std::streamsize>(pixels.size()));
    EXPECT_EQ(pixels, expected_srgb(image));
    EXPECT_EQ(file.get(), std::char_traits<char>::eof());
}

TEST(ImageFile, AFullDeviceIsAReportedFailure) {
    if (!std::filesystem::exists("/dev/full")) {
        GTEST_SKIP() << "no /dev/full";
    }
    const auto grey = [](int, std::uint8_t* rgb) { std::fill_n(rgb, 64 * 3, 200); };
    // /dev/full accepts the open and fails every write with ENOSPC: the failure must surface
    // from the buffered writes or the final flush, for both formats (named through links).
    for (const char* name : {"full.png", "full.ppm"}) {
        const std::filesystem::path link = scratch(name);
        std::filesystem::remove(link);
        std::filesystem::create_symlink("/dev/full", link);
        EXPECT_NE(detail::write_plain_image(link.string(), 64, 64, grey), "") << name;
    }
}

TEST(ImageFile, AFailedWriteLeavesNoFileBehind) {
    const RenderedImage image = gradient_image(8, 8);
    const std::filesystem::path folder = scratch("missing-folder") / "x.png";
    EXPECT_THROW(write_image(image, folder.string()), ResourceLimit);
    EXPECT_FALSE(std::filesystem::exists(folder));
    EXPECT_FALSE(std::filesystem::exists(partial_path(folder.string())));
}

}  // namespace
}  // namespace locus::render
