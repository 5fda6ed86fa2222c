// The TOML scene reader (render/scene_file.h), both forms: [[surface]] lists and [[object]]
// SDF trees. Equations are compiled as the command line does; `param` files are not read (a
// fuzzer must not open paths it invents) and stand for the unit sphere. A scene that parses is
// framed as render would do next: its first surface fitted to its extent (render/framing.h)
// and the camera built. Fitting stops with a Timeout after 2 s.
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "algebra/compiled.h"
#include "algebra/error.h"
#include "render/camera.h"
#include "render/framing.h"
#include "render/scene_file.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto text = locus::fuzz::input_text(data, size);
    if (!text) {
        return 0;
    }
    const auto compile = [](const locus::render::AlgebraicSource& source) {
        return locus::algebra::compile_surface(
            source.equation.empty() ? std::string_view("x^2+y^2+z^2-1") : source.equation);
    };
    try {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
        locus::render::Scene scene = locus::render::parse_scene(*text, compile, {}, deadline);
        if (scene.width < 1 || scene.height < 1) {
            locus::fuzz::property_failed("a parsed scene has a positive size", *text);
        }
        if (!scene.surfaces.empty()) {
            scene.surfaces.resize(1);
            const locus::algebra::CompiledPolynomial surface[] = {
                compile({scene.surfaces[0].equation, scene.surfaces[0].param_file, "surface"})};
            locus::render::fit_clip_regions(scene, surface, false, deadline);
            const locus::render::ClipSphere clip =
                locus::render::bounding_sphere(scene.surfaces[0].clip);
            if (!(clip.radius > 0.0) || !std::isfinite(clip.radius)) {
                locus::fuzz::property_failed("a fitted clip sphere has a finite radius", *text);
            }
        }
        const locus::render::Camera camera(locus::render::default_camera(scene), scene.width,
                                           scene.height);
        static_cast<void>(camera.ray(0.5, 0.5));
    } catch (const locus::Error&) {
    }
    return 0;
}
