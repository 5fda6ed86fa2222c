#include "bench/surf_run.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>

namespace locus::bench {

RunTimes summary_of(std::vector<double> times) {
    std::sort(times.begin(), times.end());
    const std::size_t middle = times.size() / 2;
    return RunTimes{
        times.size() % 2 == 1 ? times[middle] : 0.5 * (times[middle - 1] + times[middle]),
        times.front()};
}

double time_command(const std::string& command) {
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return status == 0 ? seconds : -1.0;
}

SurfRun::SurfRun(std::string surf, const SuiteSurface& s, int size)
    : surf_(std::move(surf)), surface_(s), size_(size) {
    const auto dir = std::filesystem::temp_directory_path();
    const std::string stem = "locus-surf-" + std::to_string(::getpid());
    script_ = dir / (stem + ".pic");
    image_ = dir / (stem + ".ppm");
}

SurfRun::~SurfRun() {
    std::error_code ignored;
    std::filesystem::remove(script_, ignored);
    std::filesystem::remove(image_, ignored);
}

double SurfRun::operator()(bool draw) const {
    {
        std::ofstream out(script_);
        // surf's view spans about ±10/scale world units and its clip radius is in those
        // screen units: this frames the clip sphere as locus' default camera does.
        const double scale = 0.1126 * surface_.clip_radius;
        out << "width = " << size_ << ";\nheight = " << size_ << ";\n"
            << "clip = sphere;\nradius = " << surface_.clip_radius / scale << ";\n"
            << "scale_x = " << scale << ";\nscale_y = " << scale << ";\nscale_z = " << scale
            << ";\n"
            << "surface = " << surface_.equation << ";\n";
        if (draw) {
            out << "clear_screen;\ndraw_surface;\nfilename = \"" << image_.string()
                << "\";\ncolor_file_format = ppm;\nsave_color_image;\n";
        }
    }
    std::error_code ignored;
    std::filesystem::remove(image_, ignored);
    const double seconds =
        time_command("timeout 120 " + surf_ + " -n " + script_.string() + " >/dev/null 2>&1");
    return seconds >= 0.0 && (!draw || std::filesystem::exists(image_)) ? seconds : -1.0;
}

}  // namespace locus::bench
