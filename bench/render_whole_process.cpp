#include "bench/render_whole_process.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "algebra/compiled.h"
#include "bench/surf_run.h"
#include "cli/exit_codes.h"

namespace locus::bench {

namespace {

// '…' quoted for the shell (suite equations and temporary paths hold no quote).
std::string quoted(const std::string& text) {
    return "'" + text + "'";
}

std::string ratio_text(double locus, double surf) {
    char text[16] = "-";
    if (locus > 0.0 && surf > 0.0) {
        std::snprintf(text, sizeof text, "%.2f", locus / surf);
    }
    return text;
}

}  // namespace

int run_whole_process_comparison(const std::vector<SuiteSurface>& suite,
                                 const WholeProcessArgs& args) {
    const std::filesystem::path image = std::filesystem::temp_directory_path() /
                                        ("locus-whole-" + std::to_string(::getpid()) + ".png");
    if (args.csv) {
        std::cout << "case,degree,method,size,locus_seconds,surf_seconds,ratio,locus_best_seconds,"
                     "surf_best_seconds,best_ratio\n";
    } else {
        std::printf("%-18s %3s %-9s %5s %9s %9s %6s %9s %9s %6s\n", "case", "deg", "method", "size",
                    "locus s", "surf s", "ratio", "locus min", "surf min", "ratio");
    }
    const std::string size = std::to_string(args.size) + "x" + std::to_string(args.size);
    for (const SuiteSurface& s : suite) {
        const int degree = algebra::compile_surface(s.equation).degree();
        char radius[32];
        std::snprintf(radius, sizeof radius, "%.17g", s.clip_radius);
        const std::string locus_command =
            "timeout 120 " + quoted(args.locus) + " render " + quoted(s.equation) + " -o " +
            quoted(image.string()) + " --size " + size + " --clip-radius " + radius +
            " --shadows off" + (args.method.empty() ? "" : " --method " + args.method) +
            " >/dev/null 2>&1";
        std::optional<SurfRun> surf;
        if (!args.surf.empty()) {
            surf.emplace(args.surf, s, args.size);
        }
        std::vector<double> locus_times, surf_times;
        double locus_total = 0.0;
        bool ok = true, surf_ok = surf.has_value();
        for (int round = 0; round < 15 && ok; ++round) {
            if (round >= 5 && locus_total >= args.min_seconds) {
                break;
            }
            const double locus_seconds = time_command(locus_command);
            ok = locus_seconds >= 0.0;
            locus_times.push_back(locus_seconds);
            locus_total += locus_seconds;
            if (surf_ok) {
                const double surf_seconds = (*surf)(true);
                surf_ok = surf_seconds >= 0.0;
                surf_times.push_back(surf_seconds);
            }
        }
        if (!ok) {
            std::fprintf(stderr, "%s: locus render failed: %s\n", s.name.c_str(),
                         locus_command.c_str());
            std::error_code ignored;
            std::filesystem::remove(image, ignored);
            return cli::exit_internal;
        }
        const RunTimes mine = summary_of(locus_times);
        const RunTimes theirs = surf_ok ? summary_of(surf_times) : RunTimes{};
        if (args.csv) {
            std::cout << s.name << "," << degree << ","
                      << (args.method.empty() ? "default" : args.method) << "," << args.size << ","
                      << mine.median << "," << theirs.median << ","
                      << ratio_text(mine.median, theirs.median) << "," << mine.best << ","
                      << theirs.best << "," << ratio_text(mine.best, theirs.best) << "\n";
        } else {
            std::printf("%-18s %3d %-9s %5d %9.4f %9.4f %6s %9.4f %9.4f %6s\n", s.name.c_str(),
                        degree, args.method.empty() ? "default" : args.method.c_str(), args.size,
                        mine.median, theirs.median, ratio_text(mine.median, theirs.median).c_str(),
                        mine.best, theirs.best, ratio_text(mine.best, theirs.best).c_str());
        }
        std::cout.flush();
    }
    std::error_code ignored;
    std::filesystem::remove(image, ignored);
    return cli::exit_ok;
}

}  // namespace locus::bench
