// The .param reader (implicit/parametrization.h) on arbitrary bytes: a parametrization, or a
// locus::Error with line and column.
#include <cstddef>
#include <cstdint>

#include "algebra/error.h"
#include "implicit/parametrization.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto text = locus::fuzz::input_text(data, size);
    if (!text) {
        return 0;
    }
    try {
        const locus::implicit::Parametrization map = locus::implicit::parse_parametrization(*text);
        if (map.components.size() != map.coordinates.size() || map.coordinates.size() < 2) {
            locus::fuzz::property_failed("one component per coordinate, at least x and y", *text);
        }
        if (map.circle_ring && map.circle_components.size() != map.components.size()) {
            locus::fuzz::property_failed("the map as written has every component", *text);
        }
    } catch (const locus::Error&) {
    }
    return 0;
}
