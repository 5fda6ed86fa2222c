// One dispatch from a ball's degree to a kernel compiled for it: the subdivisions and sign
// counts of the certified search are most of a frame at degree ≤ 12, and with the degree known
// at compile time their loops unroll and a row of de Casteljau's triangle stays in registers.
#pragma once

#include <type_traits>

namespace locus::render::detail {

// kernel(std::integral_constant<int, degree>{}) for degrees 0–12, and
// kernel(std::integral_constant<int, -1>{}) for every other degree (the kernel then reads the
// degree from its data). Always inlined: as a call of its own it cost a degree-8 frame 3 %.
template <class Kernel>
[[gnu::always_inline]] inline decltype(auto) with_fixed_degree(int degree, Kernel&& kernel) {
    switch (degree) {
    case 0:
        return kernel(std::integral_constant<int, 0>{});
    case 1:
        return kernel(std::integral_constant<int, 1>{});
    case 2:
        return kernel(std::integral_constant<int, 2>{});
    case 3:
        return kernel(std::integral_constant<int, 3>{});
    case 4:
        return kernel(std::integral_constant<int, 4>{});
    case 5:
        return kernel(std::integral_constant<int, 5>{});
    case 6:
        return kernel(std::integral_constant<int, 6>{});
    case 7:
        return kernel(std::integral_constant<int, 7>{});
    case 8:
        return kernel(std::integral_constant<int, 8>{});
    case 9:
        return kernel(std::integral_constant<int, 9>{});
    case 10:
        return kernel(std::integral_constant<int, 10>{});
    case 11:
        return kernel(std::integral_constant<int, 11>{});
    case 12:
        return kernel(std::integral_constant<int, 12>{});
    default:
        return kernel(std::integral_constant<int, -1>{});
    }
}

}  // namespace locus::render::detail
