// The .param reader (implicit/parametrization.h) and the .bpt reader (implicit/bezier_patch.h)
// on arbitrary bytes: a parametrization (or patches), or a locus::Error with line and column.
// Small patches are also turned into their maps.
#include <cstddef>
#include <cstdint>

#include "algebra/error.h"
#include "implicit/bezier_patch.h"
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
        if (!map.domain.empty()) {
            if (map.domain.size() != map.parameter_ring->num_vars()) {
                locus::fuzz::property_failed("a domain interval per parameter", *text);
            }
            for (const auto& [lo, hi] : map.domain) {
                if (!(lo < hi)) {
                    locus::fuzz::property_failed("domain intervals with lo < hi", *text);
                }
            }
        }
    } catch (const locus::Error&) {
    }
    try {
        const auto patches = locus::implicit::parse_bpt(*text);
        for (const auto& patch : patches) {
            const std::size_t expected = patch.kind == locus::implicit::BezierPatch::Kind::tensor
                                             ? (patch.degree_s + 1) * (patch.degree_t + 1)
                                             : (patch.degree_s + 1) * (patch.degree_s + 2) / 2;
            if (patch.points.size() != expected) {
                locus::fuzz::property_failed("a control point per Bernstein polynomial", *text);
            }
        }
        if (patches.size() <= 4) {
            for (const auto& patch : patches) {
                if (patch.degree_s <= 6 && patch.degree_t <= 6) {
                    const auto map = locus::implicit::to_parametrization(patch);
                    if (map.components.size() != 3) {
                        locus::fuzz::property_failed("a patch maps to x, y, z", *text);
                    }
                }
            }
        }
    } catch (const locus::Error&) {
    }
    return 0;
}
