#include "render/detail/png_encoder.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <new>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <isa-l.h>
#include <isa-l/igzip_lib.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <zlib.h>

#include "algebra/error.h"
#include "render/detail/thread_scratch.h"

namespace locus::render::detail {

namespace {

// ISA-L's igzip at its level 1 and the Sub filter on every row. Rendered pictures are mostly
// flat background and smooth shading, which Sub predicts. igzip, with its hash and Huffman
// coding in vector code, makes this writer 0.28–0.41 of the time of the zlib (level 2) writer
// it replaced, on one thread, for files within 3 % (`locus-bench png`): the encoding had been
// a tenth of a whole `locus render`.
constexpr int kLevel = 1;
// The ISA-L library's file name (its soname, from the version of the headers compiled against),
// for dlopen.
#define LOCUS_STRING(x) #x
#define LOCUS_EXPAND_STRING(x) LOCUS_STRING(x)
constexpr const char* kIgzipLibrary = "libisal.so." LOCUS_EXPAND_STRING(ISAL_MAJOR_VERSION);
#undef LOCUS_EXPAND_STRING
#undef LOCUS_STRING
constexpr std::uint8_t kSubFilter = 1;
// The zlib header for a 32 KiB window at a fast level (RFC 1950: CMF 0x78, FLEVEL 1, and the
// check bits that make 0x785E a multiple of 31).
constexpr std::array<std::uint8_t, 2> kZlibHeader = {0x78, 0x5E};
// Rows per band at least: a band restarts the compressor's dictionary, so a smaller one costs
// ratio (a few hundred bytes a band) for no gain in balance.
constexpr int kMinimumBandRows = 16;

struct Band {
    std::string deflated;
    uLong adler = 1;        // adler32 of the band's filtered rows
    std::size_t bytes = 0;  // their length
};

// ISA-L, loaded with dlopen on the first PNG rather than linked: linked, loading it cost every
// command 0.4–0.7 ms of start-up (`perf stat -r 30 locus --help`), `locus groebner` and `locus
// trace` included, which write no PNG. Debian's libisal2 (a dependency of libisal-dev).
struct Igzip {
    void (*deflate_init)(isal_zstream*);
    int (*deflate)(isal_zstream*);
    std::uint32_t (*adler32)(std::uint32_t, const unsigned char*, std::uint64_t);
};

const Igzip& igzip() {
    static const Igzip loaded = [] {
        void* library = dlopen(kIgzipLibrary, RTLD_NOW | RTLD_LOCAL);
        // Not there (or not usable): the picture cannot be written here, as with a full disk
        // — a ResourceLimit (exit code 5), not the input's fault.
        if (library == nullptr) {
            throw ResourceLimit(std::string("cannot write PNG: ISA-L (") + kIgzipLibrary +
                                ", Debian package libisal2) cannot be loaded: " + dlerror());
        }
        const auto symbol = [library](const char* name) {
            void* address = dlsym(library, name);
            if (address == nullptr) {
                throw ResourceLimit(std::string("cannot write PNG: ") + kIgzipLibrary + " lacks " +
                                    name);
            }
            return address;
        };
        Igzip functions{};
        functions.deflate_init =
            reinterpret_cast<void (*)(isal_zstream*)>(symbol("isal_deflate_init"));
        functions.deflate = reinterpret_cast<int (*)(isal_zstream*)>(symbol("isal_deflate"));
        functions.adler32 =
            reinterpret_cast<std::uint32_t (*)(std::uint32_t, const unsigned char*, std::uint64_t)>(
                symbol("isal_adler32"));
        return functions;
    }();
    return loaded;
}

// igzip's state for one stream (82 KB) and its level's buffer (hash table and tokens) in one
// block. The small buffer (84 KB) compressed a 512² frame within 0.2 % of the default (276 KB)
// and as fast, and in ordinary pages the block cost a whole command no more than the default's
// in a 2 MB large page (measured when it was chosen, 2026-11-28: performance.md).
class DeflateStream {
  public:
    DeflateStream() : stream_(new (block_.data()) isal_zstream) {}
    DeflateStream(const DeflateStream&) = delete;
    DeflateStream& operator=(const DeflateStream&) = delete;

    // Ready for a new raw deflate stream (no zlib header or checksum of its own).
    void reset() {
        igzip().deflate_init(stream_);
        stream_->level = kLevel;
        stream_->level_buf = block_.data() + kLevelBufferOffset;
        stream_->level_buf_size = ISAL_DEF_LVL1_SMALL;
        stream_->gzip_flag = IGZIP_DEFLATE;
    }

    // Compresses `input` into `out` (grown as needed), then, with `sync`, ends the deflate
    // block byte-aligned (so that the next band's stream can follow it), or with `last` ends
    // the stream.
    void run(const std::uint8_t* input, std::size_t size, bool sync, bool last, std::string& out) {
        stream_->next_in = const_cast<std::uint8_t*>(input);  // igzip does not write it
        stream_->avail_in = static_cast<std::uint32_t>(size);
        stream_->flush = sync ? SYNC_FLUSH : NO_FLUSH;
        stream_->end_of_stream = last ? 1 : 0;
        // Output space left over after a call: the input is consumed and the flush or the end
        // complete (igzip's own examples loop the same way).
        do {
            if (stream_->total_out == out.size()) {
                out.resize(std::max<std::size_t>(4096, 2 * out.size()));
            }
            stream_->next_out = reinterpret_cast<std::uint8_t*>(out.data()) + stream_->total_out;
            stream_->avail_out = static_cast<std::uint32_t>(out.size() - stream_->total_out);
            if (igzip().deflate(stream_) != COMP_OK) {
                throw Error("igzip deflate failed");
            }
        } while (stream_->avail_out == 0);
        if (stream_->avail_in != 0 || (last && stream_->internal_state.state != ZSTATE_END)) {
            throw Error("igzip deflate stopped short");
        }
    }
    std::size_t total_out() const { return stream_->total_out; }

  private:
    static constexpr std::size_t kLevelBufferOffset = (sizeof(isal_zstream) + 63) / 64 * 64;
    std::vector<std::uint8_t> block_ =
        std::vector<std::uint8_t>(kLevelBufferOffset + ISAL_DEF_LVL1_SMALL);
    isal_zstream* stream_;
};

Band deflate_band(int width, int first, int last, bool final, const RgbRowSource& row) {
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(width);
    std::vector<std::uint8_t> rgb(row_bytes);
    std::vector<std::uint8_t> filtered(row_bytes + 1);
    filtered[0] = kSubFilter;
    // One stream per thread, reset for each band: its 166 KB of state is allocated, and its
    // pages faulted in, once per thread rather than once per band. A band begun while this
    // thread's stream is busy (a row source that runs parallel work of its own, during which
    // the thread may take another band) gets a stream of its own.
    ThreadScratch<DeflateStream> scratch;
    DeflateStream& stream = scratch.get();
    stream.reset();
    Band band;
    // Room for a twelfth of the filtered bytes (a 512² frame's bands take a twentieth; more
    // is allocated as needed): the first frame faults in every page the buffer is given.
    band.deflated.resize((row_bytes + 1) / 12 * static_cast<std::size_t>(last - first) + 4096);
    for (int y = first; y < last; ++y) {
        row(y, rgb.data());
        // Sub: each byte less the same channel of the pixel to its left (mod 256).
        std::copy_n(rgb.begin(), std::min<std::size_t>(3, row_bytes), filtered.begin() + 1);
        for (std::size_t i = 3; i < row_bytes; ++i) {
            filtered[i + 1] = static_cast<std::uint8_t>(rgb[i] - rgb[i - 3]);
        }
        band.adler = igzip().adler32(static_cast<std::uint32_t>(band.adler), filtered.data(),
                                     filtered.size());
        band.bytes += filtered.size();
        const bool band_ends = y + 1 == last;
        stream.run(filtered.data(), filtered.size(), band_ends && !final, band_ends && final,
                   band.deflated);
    }
    band.deflated.resize(stream.total_out());
    return band;
}

void put_u32(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) {
        out.push_back(static_cast<char>((value >> shift) & 0xFF));
    }
}

// Appends the chunk `type` with `data` and its CRC (over the type and the data).
void put_chunk(std::string& out, const char (&type)[5], const std::string& data) {
    put_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.append(type, 4);
    out.append(data);
    const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(out.data() + start),
                            static_cast<uInt>(out.size() - start));
    put_u32(out, static_cast<std::uint32_t>(crc));
}

}  // namespace

namespace {

// Every band of the image filtered and deflated, side by side.
std::vector<Band> deflate_bands(int width, int height, const RgbRowSource& row) {
    if (width <= 0 || height <= 0) {
        throw Error("encode_png: an image needs a positive width and height");
    }
    const int concurrency = std::max(1, tbb::this_task_arena::max_concurrency());
    const int bands = std::clamp(height / kMinimumBandRows, 1, 2 * concurrency);
    std::vector<Band> deflated(static_cast<std::size_t>(bands));
    tbb::parallel_for(0, bands, [&](int b) {
        const int first = static_cast<int>(static_cast<long>(height) * b / bands);
        const int last = static_cast<int>(static_cast<long>(height) * (b + 1) / bands);
        deflated[static_cast<std::size_t>(b)] =
            deflate_band(width, first, last, b + 1 == bands, row);
    });
    return deflated;
}

// The file in pieces, in order: the signature, IHDR and the head of the IDAT chunk; each band's
// deflated bytes as they are; the zlib checksum, IDAT's CRC (taken over the pieces) and IEND.
// Not gathered into one buffer first: at 512² that buffer and its copy were two blocks of
// 100–150 KB of fresh memory, some sixty page faults, on the end of the command's critical path.
void emit_png(int width, int height, const std::vector<Band>& bands, const PngSink& put) {
    std::size_t idat_bytes = kZlibHeader.size() + 4;
    for (const Band& band : bands) {
        idat_bytes += band.deflated.size();
    }
    if (idat_bytes > 0x7FFFFFFF) {
        throw Error("encode_png: the image data exceeds one PNG chunk");
    }
    std::string header;
    put_u32(header, static_cast<std::uint32_t>(width));
    put_u32(header, static_cast<std::uint32_t>(height));
    header +=
        std::string{8, 2, 0, 0, 0};  // 8 bits, truecolour, deflate, adaptive filters, no interlace

    std::string head("\x89PNG\r\n\x1a\n", 8);
    put_chunk(head, "IHDR", header);
    put_u32(head, static_cast<std::uint32_t>(idat_bytes));
    const std::size_t crc_from = head.size();  // IDAT's CRC covers its type and its data
    head.append("IDAT", 4);
    head.append(kZlibHeader.begin(), kZlibHeader.end());
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(head.data() + crc_from),
                      static_cast<uInt>(head.size() - crc_from));
    put(head.data(), head.size());
    uLong adler = 1;
    for (const Band& band : bands) {
        crc = crc32(crc, reinterpret_cast<const Bytef*>(band.deflated.data()),
                    static_cast<uInt>(band.deflated.size()));
        adler = adler32_combine(adler, band.adler, static_cast<z_off_t>(band.bytes));
        put(band.deflated.data(), band.deflated.size());
    }
    std::string tail;
    put_u32(tail, static_cast<std::uint32_t>(adler));
    crc = crc32(crc, reinterpret_cast<const Bytef*>(tail.data()), static_cast<uInt>(tail.size()));
    put_u32(tail, static_cast<std::uint32_t>(crc));
    put_chunk(tail, "IEND", std::string());
    put(tail.data(), tail.size());
}

}  // namespace

std::string encode_png(int width, int height, const RgbRowSource& row) {
    std::string png;
    encode_png(width, height, row,
               [&png](const char* data, std::size_t size) { png.append(data, size); });
    return png;
}

void encode_png(int width, int height, const RgbRowSource& row, const PngSink& put) {
    emit_png(width, height, deflate_bands(width, height, row), put);
}

void prepare_png_encoder() {
    try {
        igzip();
    } catch (const Error&) {
        // The first encoding tries again and reports it.
    }
}

}  // namespace locus::render::detail
