// The polynomial, ideal-file and msolve-file parsers (algebra/parse.h) and the readers of pasted
// Singular and Macaulay2 sessions (algebra/system_input.h) on arbitrary bytes: every
// input is either an ideal or a ParseError/InputError/ResourceLimit (locus::Error); anything
// else (another exception, a crash, undefined behaviour, a leak) is a bug.
#include <cstddef>
#include <cstdint>

#include "algebra/error.h"
#include "algebra/parse.h"
#include "algebra/system_input.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto text = locus::fuzz::input_text(data, size);
    if (!text) {
        return 0;
    }
    // Format detection runs on everything, as `locus groebner -` runs it.
    (void)locus::algebra::detect_ideal_format(*text);
    for (const auto parse :
         {locus::algebra::parse_ideal_file, locus::algebra::parse_msolve_file,
          locus::algebra::parse_singular_input, locus::algebra::parse_macaulay2_input}) {
        try {
            const locus::algebra::IdealFile file = parse(*text);
            if (file.generators.size() != file.generator_lines.size()) {
                locus::fuzz::property_failed("one line number per generator", *text);
            }
            for (const auto& g : file.generators) {
                if (g.is_zero()) {
                    locus::fuzz::property_failed("zero generators are dropped", *text);
                }
            }
        } catch (const locus::Error&) {
        }
    }
    return 0;
}
