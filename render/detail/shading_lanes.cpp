#include "render/detail/shading_lanes.h"

#include <cmath>
#include <cstdint>

#include <immintrin.h>

// GCC 12 sees the _mm512_undefined_* inside AVX-512 intrinsics as uninitialized reads (GCC bug
// 105593); the intrinsics are correct.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#pragma GCC diagnostic ignored "-Wuninitialized"

namespace locus::render::detail {

void HitLanes::resize(std::size_t n, std::size_t lights) {
    for (std::vector<double>* v : {&dx, &dy, &dz, &gx, &gy, &gz, &nx, &ny, &nz, &vx, &vy, &vz, &bx,
                                   &by, &bz, &ambient, &diffuse, &specular}) {
        v->resize(n);
    }
    outside.resize(n);
    shininess.resize(n);
    visible.resize(n * lights);
}

namespace {

#define LOCUS_AVX512 __attribute__((target("avx512f")))

LOCUS_AVX512 inline __mmask8 lanes_from(std::size_t i, std::size_t n) {
    return n - i >= 8 ? __mmask8{0xFF} : static_cast<__mmask8>((1u << (n - i)) - 1u);
}

LOCUS_AVX512 inline __m512d dot8(__m512d ax, __m512d ay, __m512d az, __m512d bx, __m512d by,
                                 __m512d bz) {
    return _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ax, bx), _mm512_mul_pd(ay, by)),
                         _mm512_mul_pd(az, bz));
}

LOCUS_AVX512 inline __m512d load_lanes(const std::vector<double>& a, std::size_t i, __mmask8 in) {
    return _mm512_maskz_loadu_pd(in, a.data() + i);
}

LOCUS_AVX512 inline __m512d negated(__m512d x) {
    return _mm512_castsi512_pd(
        _mm512_xor_si512(_mm512_castpd_si512(x), _mm512_set1_epi64(INT64_MIN)));
}

// One channel of blinn_phong's light term, c += (visible·intensity)·light colour ·
// ((diffuse·cosine)·base + specular·highlight), on the lit lanes (its ·Vec3(1.0) changes no
// value: x·1 = x).
LOCUS_AVX512 inline __m512d add_light(__m512d c, __mmask8 lit, __m512d weight, double light_color,
                                      __m512d diffuse_cosine, __m512d base, __m512d shine) {
    const __m512d term = _mm512_add_pd(_mm512_mul_pd(diffuse_cosine, base), shine);
    return _mm512_mask_add_pd(
        c, lit, c, _mm512_mul_pd(_mm512_mul_pd(weight, _mm512_set1_pd(light_color)), term));
}

}  // namespace

// The view vector and facing_side of hits [0, n).
LOCUS_AVX512 void facing_sides_avx512(HitLanes& h, std::size_t n) {
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    const __m512d infinity = _mm512_set1_pd(INFINITY);
    for (std::size_t i = 0; i < n; i += 8) {
        const __mmask8 in = lanes_from(i, n);
        const __m512d dx = load_lanes(h.dx, i, in), dy = load_lanes(h.dy, i, in),
                      dz = load_lanes(h.dz, i, in);
        const __m512d to_unit = _mm512_div_pd(one, _mm512_sqrt_pd(dot8(dx, dy, dz, dx, dy, dz)));
        const __m512d vx = negated(_mm512_mul_pd(dx, to_unit));
        const __m512d vy = negated(_mm512_mul_pd(dy, to_unit));
        const __m512d vz = negated(_mm512_mul_pd(dz, to_unit));
        const __m512d gx = load_lanes(h.gx, i, in), gy = load_lanes(h.gy, i, in),
                      gz = load_lanes(h.gz, i, in);
        const __m512d length = _mm512_sqrt_pd(dot8(gx, gy, gz, gx, gy, gz));
        const __mmask8 usable = _mm512_cmp_pd_mask(length, zero, _CMP_GT_OQ) &
                                _mm512_cmp_pd_mask(length, infinity, _CMP_LT_OQ);
        const __m512d to_normal = _mm512_div_pd(one, length);
        __m512d nx = _mm512_mul_pd(gx, to_normal), ny = _mm512_mul_pd(gy, to_normal),
                nz = _mm512_mul_pd(gz, to_normal);
        const __mmask8 inside =
            _mm512_cmp_pd_mask(dot8(nx, ny, nz, vx, vy, vz), zero, _CMP_LT_OQ) & usable;
        nx = _mm512_mask_blend_pd(usable, vx, _mm512_mask_blend_pd(inside, nx, negated(nx)));
        ny = _mm512_mask_blend_pd(usable, vy, _mm512_mask_blend_pd(inside, ny, negated(ny)));
        nz = _mm512_mask_blend_pd(usable, vz, _mm512_mask_blend_pd(inside, nz, negated(nz)));
        _mm512_mask_storeu_pd(h.nx.data() + i, in, nx);
        _mm512_mask_storeu_pd(h.ny.data() + i, in, ny);
        _mm512_mask_storeu_pd(h.nz.data() + i, in, nz);
        _mm512_mask_storeu_pd(h.vx.data() + i, in, vx);
        _mm512_mask_storeu_pd(h.vy.data() + i, in, vy);
        _mm512_mask_storeu_pd(h.vz.data() + i, in, vz);
        for (std::size_t k = 0; k < 8 && i + k < n; ++k) {
            h.outside[i + k] = ((inside >> k) & 1u) == 0 ? 1 : 0;
        }
    }
}

// blinn_phong of hits [0, n) with an ambient factor of 1, for directional lights, into
// out[i].color (and the normals into out[i].normal).
LOCUS_AVX512 void blinn_phong_avx512(const HitLanes& h, std::size_t n,
                                     std::span<const Light> lights, bool shadows,
                                     ShadingResult* out) {
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    alignas(64) double red[8], green[8], blue[8];
    for (std::size_t i = 0; i < n; i += 8) {
        const __mmask8 in = lanes_from(i, n);
        const __m512d nx = load_lanes(h.nx, i, in), ny = load_lanes(h.ny, i, in),
                      nz = load_lanes(h.nz, i, in);
        const __m512d vx = load_lanes(h.vx, i, in), vy = load_lanes(h.vy, i, in),
                      vz = load_lanes(h.vz, i, in);
        const __m512d bx = load_lanes(h.bx, i, in), by = load_lanes(h.by, i, in),
                      bz = load_lanes(h.bz, i, in);
        const __m512d ambient = load_lanes(h.ambient, i, in),
                      diffuse = load_lanes(h.diffuse, i, in),
                      specular = load_lanes(h.specular, i, in);
        const __m512i exponent = _mm512_maskz_loadu_epi64(in, h.shininess.data() + i);
        __m512d cx = _mm512_mul_pd(ambient, bx), cy = _mm512_mul_pd(ambient, by),
                cz = _mm512_mul_pd(ambient, bz);
        for (std::size_t l = 0; l < lights.size(); ++l) {
            const Light& light = lights[l];
            const __m512d lx = _mm512_set1_pd(light.direction.x),
                          ly = _mm512_set1_pd(light.direction.y),
                          lz = _mm512_set1_pd(light.direction.z);
            const __m512d cosine = dot8(nx, ny, nz, lx, ly, lz);
            // blinn_phong skips a light when cosine <= 0 or visible <= 0: a NaN goes on.
            __mmask8 lit = _mm512_cmp_pd_mask(cosine, zero, _CMP_NLE_UQ) & in;
            __m512d visible = one;
            if (shadows) {
                visible = _mm512_maskz_loadu_pd(in, h.visible.data() + l * n + i);
                lit &= _mm512_cmp_pd_mask(visible, zero, _CMP_NLE_UQ);
            }
            if (lit == 0) {
                continue;
            }
            const __m512d hx = _mm512_add_pd(lx, vx), hy = _mm512_add_pd(ly, vy),
                          hz = _mm512_add_pd(lz, vz);
            const __m512d to_unit =
                _mm512_div_pd(one, _mm512_sqrt_pd(dot8(hx, hy, hz, hx, hy, hz)));
            const __m512d facing = dot8(nx, ny, nz, _mm512_mul_pd(hx, to_unit),
                                        _mm512_mul_pd(hy, to_unit), _mm512_mul_pd(hz, to_unit));
            // specular_power(max(0, facing), e): square and multiply, lane by lane.
            __m512d highlight = one, square = _mm512_max_pd(facing, zero);
            __m512i bits = exponent;
            for (__mmask8 left = _mm512_test_epi64_mask(bits, bits) & lit; left != 0;
                 left = _mm512_test_epi64_mask(bits, bits) & lit) {
                const __mmask8 odd = _mm512_test_epi64_mask(bits, _mm512_set1_epi64(1)) & lit;
                highlight = _mm512_mask_mul_pd(highlight, odd, highlight, square);
                square = _mm512_mul_pd(square, square);
                bits = _mm512_srli_epi64(bits, 1);
            }
            const __m512d weight = _mm512_mul_pd(visible, _mm512_set1_pd(light.intensity));
            const __m512d diffuse_cosine = _mm512_mul_pd(diffuse, cosine);
            const __m512d shine = _mm512_mul_pd(specular, highlight);
            cx = add_light(cx, lit, weight, light.color.x, diffuse_cosine, bx, shine);
            cy = add_light(cy, lit, weight, light.color.y, diffuse_cosine, by, shine);
            cz = add_light(cz, lit, weight, light.color.z, diffuse_cosine, bz, shine);
        }
        _mm512_store_pd(red, cx);
        _mm512_store_pd(green, cy);
        _mm512_store_pd(blue, cz);
        for (std::size_t k = 0; k < 8 && i + k < n; ++k) {
            out[i + k].color = {red[k], green[k], blue[k]};
            out[i + k].normal = {h.nx[i + k], h.ny[i + k], h.nz[i + k]};
        }
    }
}

#undef LOCUS_AVX512

}  // namespace locus::render::detail
