// The requests of `locus view` (view/frame_builder.h) on arbitrary bytes, as the page's form
// fields: one `name=value` a line (a value may hold anything but a newline). Every input is a
// frame or a refusal (RequestError, or a locus::Error from the equation); the frame, rendered at
// its small size, is an image or a Timeout. Anything else (another exception, a crash,
// undefined behaviour, a leak) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "algebra/error.h"
#include "render/renderer.h"
#include "tests/fuzz/fuzz_input.h"
#include "view/frame_builder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto text = locus::fuzz::input_text(data, size);
    if (!text) {
        return 0;
    }
    locus::view::Fields fields;
    std::size_t start = 0;
    while (start <= text->size()) {
        const std::size_t end = std::min(text->find('\n', start), text->size());
        const std::string line(*text, start, end - start);
        const std::size_t equals = line.find('=');
        if (equals != std::string::npos) {
            fields.emplace(line.substr(0, equals), line.substr(equals + 1));
        }
        start = end + 1;
    }
    locus::view::ViewOptions options;
    options.limits.max_image_side = 12;  // small frames: the fuzzer is after the parsing
    options.limits.max_equation_chars = 300;
    options.limits.fit_seconds = 0.2;
    options.render_threads = 1;
    locus::view::FrameBuilder builder(options);
    try {
        locus::view::Frame frame = builder.build(fields);
        frame.scene.options.shadows = false;
        locus::render::ExecutionSettings execution;
        execution.threads = 1;
        execution.aovs = false;
        execution.deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
        const locus::render::RenderedImage image =
            locus::render::render(frame.scene, frame.compiled, execution);
        if (image.width != frame.scene.width || image.height != frame.scene.height) {
            locus::fuzz::property_failed("the frame has the size asked for", *text);
        }
    } catch (const locus::view::RequestError&) {
    } catch (const locus::Error&) {
    }
    return 0;
}
