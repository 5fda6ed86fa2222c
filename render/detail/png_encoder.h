// 8-bit RGB PNG encoded in parallel bands of rows, as pigz compresses gzip: each band is filtered
// and deflated on its own (ended by a sync flush, so that the pieces concatenate into one deflate
// stream), and the zlib checksum is combined from the bands'. libspng deflates on one thread,
// after the frame: 3.5–4 ms of a 512² frame, all of it on the whole command's critical path.
// Rows are asked for as they are compressed, so the caller converts its colours to 8-bit codes
// band by band, on the same threads, without a frame-sized buffer of codes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace locus::render::detail {

// Writes the 3·width bytes of row y (0 at the top) as interleaved 8-bit RGB. Called once for each
// row, from any thread, rows of one band in order.
using RgbRowSource = std::function<void(int y, std::uint8_t* rgb)>;

// The PNG file of a width×height image (both positive), 8-bit truecolour, not interlaced. Throws
// std::bad_alloc when the compressor's state cannot be allocated, Error when its library (ISA-L,
// loaded on first use) cannot be loaded.
std::string encode_png(int width, int height, const RgbRowSource& row);

// Receives a file's bytes, piece by piece, in order.
using PngSink = std::function<void(const char* data, std::size_t size)>;
// The same file handed to `put` in pieces (its bands as they were deflated), without a copy of
// the whole.
void encode_png(int width, int height, const RgbRowSource& row, const PngSink& put);

// Loads the compressor's library (ISA-L, loaded on first use), for a thread with nothing else
// to do before a frame. A library that cannot be loaded is reported by the first encoding.
void prepare_png_encoder();

}  // namespace locus::render::detail
