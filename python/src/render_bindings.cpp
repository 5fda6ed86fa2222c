// Rendering and ray tracing as `locus._locus` exposes them: a surface named as `locus render`
// takes it (an equation, a scene file, a parametrization or patch file) to an 8-bit sRGB NumPy
// image, and rays given as NumPy arrays to their first hits, through the same code as the CLI
// (cli/surface_input.h, cli/patch_surfaces.h, render/).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "algebra/deadline.h"
#include "algebra/error.h"
#include "cli/command_support.h"
#include "cli/patch_surfaces.h"
#include "cli/surface_input.h"
#include "python/src/bindings.h"
#include "render/framing.h"
#include "render/renderer.h"
#include "render/scene_file.h"
#include "render/sdf/sdf_renderer.h"
#include "render/shading.h"
#include "render/surface_tracer.h"
#include "render/trace_method.h"

namespace locus::python {
namespace {

render::Vec3 to_vec3(const std::vector<double>& v, const char* name) {
    if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
        throw_input_error(std::string(name) + ": expected three finite numbers");
    }
    return {v[0], v[1], v[2]};
}

struct RenderRequest {
    std::string source;
    std::string kind;  // equation, scene, param
    int width = 512, height = 512;
    std::optional<std::vector<double>> eye, target, up;
    std::optional<double> fov;
    std::optional<std::string> method;
    std::optional<int> samples;
    std::optional<bool> shadows;
    int threads = 0;
};

render::Scene scene_of(const RenderRequest& request,
                       std::chrono::steady_clock::time_point deadline) {
    std::optional<render::TraceMethod> method;
    if (request.method) {
        method = render::parse_trace_method(*request.method);
    }
    const cli::SourceKind kind = request.kind == "scene"   ? cli::SourceKind::scene_file
                                 : request.kind == "param" ? cli::SourceKind::param_file
                                                           : cli::SourceKind::equation;
    render::Scene scene = cli::scene_from_source(request.source, kind, method, deadline);
    if (request.width < 1 || request.height < 1 || request.width > 16384 ||
        request.height > 16384) {
        throw_input_error("size: expected (width, height), each from 1 to 16384");
    }
    scene.width = request.width;
    scene.height = request.height;
    if (request.samples) {
        if (*request.samples < 1 || *request.samples > 16) {
            throw_input_error("samples: expected N from 1 to 16 (N×N per pixel)");
        }
        scene.options.samples = *request.samples;
    }
    if (request.shadows) {
        scene.options.shadows = *request.shadows;
    }
    scene.options.threads = request.threads;
    return scene;
}

void apply_camera(const RenderRequest& request, render::Scene& scene) {
    if (!request.eye && !request.target && !request.up && !request.fov) {
        return;
    }
    render::CameraSpec camera = scene.camera.value_or(render::default_camera(scene));
    if (request.eye) {
        camera.eye = to_vec3(*request.eye, "eye");
    }
    if (request.target) {
        camera.target = to_vec3(*request.target, "target");
    }
    if (request.up) {
        camera.up = to_vec3(*request.up, "up");
    }
    if (request.fov) {
        camera.fov_degrees = *request.fov;
    }
    scene.camera = camera;
}

struct Rendered {
    render::RenderedImage image;
    render::RenderStats stats;
    render::CameraSpec camera;
};

py::tuple render_surface(const RenderRequest& request, std::optional<double> timeout) {
    const auto deadline = deadline_after(timeout);
    const Rendered rendered = run_interruptible([&] {
        render::Scene scene = scene_of(request, deadline);
        // An equation is compiled here, so that its ParseError reaches Python with its line and
        // column (the CLI's helper turns it into a message); files go through the CLI's path.
        std::vector<algebra::CompiledPolynomial> compiled;
        if (request.kind == "equation") {
            compiled.push_back(algebra::compile_surface(request.source));
        } else {
            compiled = cli::compile_surfaces(scene, deadline);
        }
        cli::frame_far_equations(scene, compiled);  // as `locus render` does
        render::fit_clip_regions(scene, compiled, false, deadline);
        apply_camera(request, scene);
        render::ExecutionSettings execution;
        execution.threads = scene.options.threads;
        execution.deadline = deadline;
        execution.aovs = true;
        Rendered r;
        r.image = scene.objects.empty()
                      ? render::render(scene, compiled, execution, &r.stats)
                      : render::render_sdf_scene(scene, compiled, execution, &r.stats);
        r.camera = scene.camera.value_or(render::default_camera(scene));
        return r;
    });
    const render::RenderedImage& image = rendered.image;
    const auto h = static_cast<py::ssize_t>(image.height);
    const auto w = static_cast<py::ssize_t>(image.width);
    py::array_t<std::uint8_t> rgb({h, w, py::ssize_t{3}});
    auto pixels = rgb.mutable_unchecked<3>();
    py::array_t<float> depth({h, w});
    auto distances = depth.mutable_unchecked<2>();
    // The other AOVs, as `locus render --aov` writes them: linear colour, unit normals (zero on
    // a miss), and the root finders' work per pixel.
    py::array_t<float> linear({h, w, py::ssize_t{3}});
    py::array_t<float> normal({h, w, py::ssize_t{3}});
    py::array_t<float> work({h, w});
    auto linear_pixels = linear.mutable_unchecked<3>();
    auto normals = normal.mutable_unchecked<3>();
    auto works = work.mutable_unchecked<2>();
    for (py::ssize_t y = 0; y < h; ++y) {
        for (py::ssize_t x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * w + x);
            for (py::ssize_t c = 0; c < 3; ++c) {
                pixels(y, x, c) =
                    render::to_srgb8(image.color[3 * i + static_cast<std::size_t>(c)]);
            }
            distances(y, x) =
                image.depth.empty() ? std::numeric_limits<float>::infinity() : image.depth[i];
            for (py::ssize_t c = 0; c < 3; ++c) {
                const std::size_t k = 3 * i + static_cast<std::size_t>(c);
                linear_pixels(y, x, c) = image.color[k];
                normals(y, x, c) = image.normal.empty() ? 0.0f : image.normal[k];
            }
            works(y, x) = image.work.empty() ? 0.0f : image.work[i];
        }
    }
    py::dict stats;
    stats["seconds"] = rendered.stats.seconds;
    stats["primary_rays"] = rendered.stats.primary_rays;
    stats["hits"] = rendered.stats.hits;
    stats["undecided"] = rendered.stats.unknown;
    const render::CameraSpec& c = rendered.camera;
    stats["camera"] = py::dict(
        py::arg("eye") = py::make_tuple(c.eye.x, c.eye.y, c.eye.z),
        py::arg("target") = py::make_tuple(c.target.x, c.target.y, c.target.z),
        py::arg("up") = py::make_tuple(c.up.x, c.up.y, c.up.z), py::arg("fov") = c.fov_degrees);
    py::dict aovs;
    aovs["linear"] = linear;
    aovs["normal"] = normal;
    aovs["work"] = work;
    return py::make_tuple(rgb, depth, stats, aovs);
}

// First hits of rays o + t·d, t in (0, t_max]: t (NaN where there is none) and a status per ray
// (1 hit, 0 miss, -1 undecided by the method).
py::tuple trace_rays(
    const std::string& equation,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& origins,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& directions,
    const std::string& method_name, double t_max, std::optional<double> timeout) {
    if (origins.ndim() != 2 || origins.shape(1) != 3 || directions.ndim() != 2 ||
        directions.shape(1) != 3 || origins.shape(0) != directions.shape(0)) {
        throw_input_error("trace: expected origins and directions of the same shape (N, 3)");
    }
    if (!(t_max > 0.0) || !std::isfinite(t_max)) {
        throw_input_error("trace: t_max must be a positive number");
    }
    const render::TraceMethod method = render::parse_trace_method(method_name);
    const algebra::CompiledPolynomial f = algebra::compile_surface(equation);
    const auto n = static_cast<std::size_t>(origins.shape(0));
    std::vector<double> o(origins.data(), origins.data() + 3 * n);
    std::vector<double> d(directions.data(), directions.data() + 3 * n);
    const auto deadline = deadline_after(timeout);
    struct Hits {
        std::vector<double> t;
        std::vector<std::int8_t> status;
    };
    const Hits hits = run_interruptible([&] {
        const render::SurfaceTracer tracer(f, method, 1.0);
        Hits out{std::vector<double>(n, std::nan("")), std::vector<std::int8_t>(n, 0)};
        for (std::size_t i = 0; i < n; ++i) {
            if (i % 256 == 0 && deadline_passed(deadline)) {
                throw Timeout("trace: " + std::to_string(i) + " of " + std::to_string(n) +
                              " rays traced");
            }
            const render::Ray ray{{o[3 * i], o[3 * i + 1], o[3 * i + 2]},
                                  {d[3 * i], d[3 * i + 1], d[3 * i + 2]}};
            const render::RootResult hit = tracer.first_hit(ray, render::Interval{0.0, t_max});
            if (hit.status == render::RootStatus::hit) {
                out.t[i] = hit.t;
                out.status[i] = 1;
            } else if (hit.status != render::RootStatus::miss) {
                out.status[i] = -1;
            }
        }
        return out;
    });
    return py::make_tuple(
        py::array_t<double>(static_cast<py::ssize_t>(n), hits.t.data()),
        py::array_t<std::int8_t>(static_cast<py::ssize_t>(n), hits.status.data()));
}

}  // namespace

void bind_render(py::module_& m) {
    m.def(
        "_render",
        [](const std::string& source, const std::string& kind, int width, int height,
           std::optional<std::vector<double>> eye, std::optional<std::vector<double>> target,
           std::optional<std::vector<double>> up, std::optional<double> fov,
           std::optional<std::string> method, std::optional<int> samples,
           std::optional<bool> shadows, int threads, std::optional<double> timeout) {
            RenderRequest request{source, kind, width,  height,  eye,     target,
                                  up,     fov,  method, samples, shadows, threads};
            return render_surface(request, timeout);
        },
        py::arg("source"), py::arg("kind"), py::arg("width"), py::arg("height"), py::arg("eye"),
        py::arg("target"), py::arg("up"), py::arg("fov"), py::arg("method"), py::arg("samples"),
        py::arg("shadows"), py::arg("threads"), py::arg("timeout"));
    m.def("_trace", &trace_rays, py::arg("equation"), py::arg("origins"), py::arg("directions"),
          py::arg("method"), py::arg("t_max"), py::arg("timeout"));
    m.def("_trace_methods", [] {
        std::vector<std::string> names;
        for (const render::TraceMethod method : render::all_trace_methods()) {
            names.emplace_back(render::to_string(method));
        }
        return names;
    });
}

}  // namespace locus::python
