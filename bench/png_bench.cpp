// `locus-bench png`: the PNG writer of `locus render` on the surface suite's frames, against
// zlib in the same run. Each surface is rendered as `locus render` renders it (certified, no
// shadows, one sample); its picture is then encoded by render::png_bytes — on one thread, to
// compare compressors, and on every core, as the command does — and, as the reference, by the
// writer locus had before (the same 8-bit codes and Sub filter, one zlib stream at level 2, on
// one thread). Rows: bytes and medians of each, and locus's one-thread time over zlib's.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <tbb/global_control.h>
#include <zlib.h>

#include "algebra/compiled.h"
#include "algebra/error.h"
#include "bench/bench_options.h"
#include "bench/benches.h"
#include "bench/surf_run.h"  // RunTimes, summary_of
#include "bench/surface_suite.h"
#include "cli/exit_codes.h"
#include "render/camera.h"
#include "render/image_output.h"
#include "render/renderer.h"
#include "render/shading.h"

namespace locus::bench {
namespace {

using cli::exit_ok;

struct PngBenchArgs {
    SuiteOptions suite;
    int size = 512;
};

// Seconds of each run of `work` until `min_seconds` have passed (at least three runs).
template <class Work>
RunTimes time_runs(const Work& work, double min_seconds) {
    std::vector<double> times;
    double total = 0.0;
    do {
        const auto start = std::chrono::steady_clock::now();
        work();
        times.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        total += times.back();
    } while (times.size() < 3 || (total < min_seconds && times.size() < 1000));
    return summary_of(std::move(times));
}

// The reference: the image's 8-bit codes, Sub-filtered row by row, in one raw zlib stream at
// level 2 with its Adler-32 (what locus wrote before igzip, without the bands). Returns the
// compressed bytes.
std::size_t zlib_level2(const render::RenderedImage& image) {
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(image.width);
    std::vector<std::uint8_t> codes(row_bytes), filtered(row_bytes + 1);
    filtered[0] = 1;  // Sub
    z_stream z{};
    if (deflateInit2(&z, 2, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
        throw Error("zlib deflateInit2 failed");
    }
    std::vector<std::uint8_t> out(row_bytes * static_cast<std::size_t>(image.height) / 2 + 4096);
    uLong adler = 1;
    for (int y = 0; y < image.height; ++y) {
        render::to_srgb8(image.color.data() + row_bytes * static_cast<std::size_t>(y), codes.data(),
                         row_bytes);
        std::copy_n(codes.begin(), std::min<std::size_t>(3, row_bytes), filtered.begin() + 1);
        for (std::size_t i = 3; i < row_bytes; ++i) {
            filtered[i + 1] = static_cast<std::uint8_t>(codes[i] - codes[i - 3]);
        }
        adler = adler32(adler, filtered.data(), static_cast<uInt>(filtered.size()));
        z.next_in = filtered.data();
        z.avail_in = static_cast<uInt>(filtered.size());
        const int flush = y + 1 < image.height ? Z_NO_FLUSH : Z_FINISH;
        int status = Z_OK;
        do {
            if (z.total_out == out.size()) {
                out.resize(2 * out.size());
            }
            z.next_out = out.data() + z.total_out;
            z.avail_out = static_cast<uInt>(out.size() - z.total_out);
            status = deflate(&z, flush);
        } while (z.avail_out == 0 || (flush == Z_FINISH && status != Z_STREAM_END));
    }
    // The stream, its zlib header and its checksum, as a file would hold them.
    const std::size_t bytes = z.total_out + 2 + sizeof(std::uint32_t);
    static_cast<void>(adler);  // computed as the old writer did (its work is timed), not kept
    deflateEnd(&z);
    return bytes;
}

int run_png_bench(const PngBenchArgs& args) {
    check_suite_options(args.suite);
    const std::vector<SuiteSurface> suite = read_surface_cases(args.suite, "png");
    if (args.suite.csv) {
        std::cout << "case,size,locus_bytes,locus_seconds_one_thread,locus_seconds_all_threads,"
                     "zlib2_bytes,zlib2_seconds,ratio_one_thread\n";
    } else {
        std::printf("%-18s %5s %11s %12s %12s %11s %11s %6s\n", "case", "size", "locus bytes",
                    "1 thread s", "all cores s", "zlib2 bytes", "zlib2 s", "ratio");
    }
    for (const SuiteSurface& s : suite) {
        const std::vector<algebra::CompiledPolynomial> compiled = {
            algebra::compile_surface(s.equation)};
        render::Scene scene;
        scene.width = scene.height = args.size;
        scene.surfaces.push_back(
            {s.equation, "", render::ClipSphere{{0, 0, 0}, s.clip_radius}, {}, ""});
        scene.options.shadows = false;
        render::ExecutionSettings execution;
        execution.aovs = false;
        const render::RenderedImage image = render::render(scene, compiled, execution);

        std::size_t locus_bytes = 0;
        const auto locus = [&] { locus_bytes = render::png_bytes(image).size(); };
        const RunTimes all = time_runs(locus, args.suite.min_seconds);
        RunTimes one;
        {
            const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
            one = time_runs(locus, args.suite.min_seconds);
        }
        std::size_t zlib_bytes = 0;
        const RunTimes zlib =
            time_runs([&] { zlib_bytes = zlib_level2(image); }, args.suite.min_seconds);
        const double ratio = one.median / zlib.median;
        if (args.suite.csv) {
            std::cout << s.name << "," << args.size << "," << locus_bytes << "," << one.median
                      << "," << all.median << "," << zlib_bytes << "," << zlib.median << ","
                      << ratio << "\n";
        } else {
            std::printf("%-18s %5d %11zu %12.5f %12.5f %11zu %11.5f %6.2f\n", s.name.c_str(),
                        args.size, locus_bytes, one.median, all.median, zlib_bytes, zlib.median,
                        ratio);
        }
        std::cout.flush();
    }
    return exit_ok;
}

}  // namespace

void add_png_bench(CLI::App& app, cli::CommandContext& context) {
    auto args = std::make_shared<PngBenchArgs>();
    CLI::App* cmd = add_suite_command(
        app, context, "png",
        "The PNG writer on the surface suite's frames against zlib at level 2 in the same run",
        args, run_png_bench);
    add_size_option(cmd, args->size, "N×N pixels per frame (512)");
}

}  // namespace locus::bench
