// The parallel PNG encoder against libspng's decoder, which shares no code with it (and checks
// every chunk's CRC and the zlib stream's Adler-32): random pictures of sizes from one pixel to
// many bands, flat, noisy and smooth, must decode to exactly the rows the encoder was given.
#include "render/detail/png_encoder.h"

#include <gtest/gtest.h>
#include <spng.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace locus::render::detail {
namespace {

struct SpngFree {
    void operator()(spng_ctx* context) const { spng_ctx_free(context); }
};

// The decoded 8-bit RGB pixels, or an empty vector (with the reason in `error`).
std::vector<std::uint8_t> decode(const std::string& png, int& width, int& height,
                                 std::string& error) {
    std::unique_ptr<spng_ctx, SpngFree> context(spng_ctx_new(0));
    spng_set_png_buffer(context.get(), png.data(), png.size());
    spng_ihdr header{};
    int status = spng_get_ihdr(context.get(), &header);
    std::size_t size = 0;
    if (status == 0) {
        status = spng_decoded_image_size(context.get(), SPNG_FMT_RGB8, &size);
    }
    std::vector<std::uint8_t> pixels(size);
    if (status == 0) {
        status = spng_decode_image(context.get(), pixels.data(), size, SPNG_FMT_RGB8, 0);
    }
    if (status != 0) {
        error = spng_strerror(status);
        return {};
    }
    width = static_cast<int>(header.width);
    height = static_cast<int>(header.height);
    EXPECT_EQ(header.bit_depth, 8);
    EXPECT_EQ(header.color_type, SPNG_COLOR_TYPE_TRUECOLOR);
    EXPECT_EQ(header.interlace_method, 0);
    return pixels;
}

// A picture with the features of a render: flat runs, gradients and noise.
std::vector<std::uint8_t> random_picture(int width, int height, std::mt19937_64& random) {
    std::vector<std::uint8_t> rgb(3 * static_cast<std::size_t>(width) * height);
    std::uniform_int_distribution<int> byte(0, 255), kind(0, 2);
    const int style = kind(random);
    const int flat = byte(random);
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const std::size_t pixel = i / 3;
        const int x = static_cast<int>(pixel % static_cast<std::size_t>(width));
        rgb[i] = static_cast<std::uint8_t>(
            style == 0   ? flat
            : style == 1 ? (x * 255 / std::max(1, width - 1) + 7 * (i % 3)) % 256
                         : byte(random));
    }
    return rgb;
}

TEST(PngEncoder, RandomPicturesDecodeToTheirRows) {
    std::mt19937_64 random(20261127);
    std::uniform_int_distribution<int> side(1, 300);
    std::vector<std::pair<int, int>> sizes = {{1, 1}, {1, 700}, {700, 1}, {2, 33}, {512, 512}};
    for (int i = 0; i < 40; ++i) {
        sizes.emplace_back(side(random), side(random));
    }
    for (const auto& [w, h] : sizes) {
        const std::vector<std::uint8_t> picture = random_picture(w, h, random);
        const std::size_t row_bytes = 3 * static_cast<std::size_t>(w);
        const std::string png = encode_png(w, h, [&](int y, std::uint8_t* rgb) {
            std::copy_n(picture.begin() + static_cast<std::ptrdiff_t>(row_bytes * y), row_bytes,
                        rgb);
        });
        int width = 0, height = 0;
        std::string error;
        const std::vector<std::uint8_t> decoded = decode(png, width, height, error);
        ASSERT_EQ(error, "") << w << "x" << h;
        EXPECT_EQ(width, w);
        EXPECT_EQ(height, h);
        ASSERT_EQ(decoded, picture) << w << "x" << h;
    }
}

TEST(PngEncoder, ARowSourceThatEncodesItselfStillGetsItsRows) {
    // A row source that runs encoding work of its own: on the thread of a band in progress,
    // bands of the inner image must not take the busy compressor over (nor must a thread that
    // waits in a row source's parallel loop and takes another band meanwhile).
    std::mt19937_64 random(5);
    const int w = 97, h = 640;
    const std::vector<std::uint8_t> picture = random_picture(w, h, random);
    const std::vector<std::uint8_t> small = random_picture(8, 40, random);
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(w);
    std::atomic<int> inner_failures{0};
    const std::string png = encode_png(w, h, [&](int y, std::uint8_t* rgb) {
        if (y % 50 == 0) {
            const std::string inner = encode_png(8, 40, [&](int yy, std::uint8_t* out) {
                std::copy_n(small.begin() + 24 * yy, 24, out);
            });
            int iw = 0, ih = 0;
            std::string error;
            if (decode(inner, iw, ih, error) != small) {
                ++inner_failures;
            }
        }
        tbb::parallel_for(std::size_t{0}, row_bytes, [&](std::size_t i) {
            rgb[i] = picture[row_bytes * static_cast<std::size_t>(y) + i];
        });
    });
    EXPECT_EQ(inner_failures.load(), 0);
    int width = 0, height = 0;
    std::string error;
    const std::vector<std::uint8_t> decoded = decode(png, width, height, error);
    ASSERT_EQ(error, "");
    EXPECT_EQ(decoded, picture);
}

TEST(PngEncoder, ACorruptedByteIsCaughtByTheDecoder) {
    // The oracle is not lenient: a flipped bit in the compressed data fails a checksum.
    std::mt19937_64 random(7);
    const std::vector<std::uint8_t> picture = random_picture(64, 64, random);
    std::string png = encode_png(64, 64, [&](int y, std::uint8_t* rgb) {
        std::copy_n(picture.begin() + 192 * y, 192, rgb);
    });
    png[png.size() / 2] = static_cast<char>(png[png.size() / 2] ^ 0x10);
    int width = 0, height = 0;
    std::string error;
    EXPECT_TRUE(decode(png, width, height, error).empty());
    EXPECT_NE(error, "");
}

TEST(PngEncoder, AnEmptyImageIsRefused) {
    const auto none = [](int, std::uint8_t*) {};
    EXPECT_ANY_THROW(encode_png(0, 5, none));
    EXPECT_ANY_THROW(encode_png(5, -1, none));
}

}  // namespace
}  // namespace locus::render::detail
