// Restriction of a compiled trivariate polynomial to a line: F(t) = f(o + t·d) as a
// RayPolynomial, for rays that do not belong to the per-frame primary family (shadow and
// ambient-occlusion rays, `locus trace`, the rows of the family itself).
//
// Terms are grouped once as f = Σ_a x^a · Σ_b y^b · Σ_c coef·z^c, and the restriction is
// evaluated in that nested form with the power tables of the three linear coordinates, which
// costs O(#terms · degree) plus small convolutions, never a full symbolic expansion.
#pragma once

#include <span>
#include <vector>

#include "algebra/compiled.h"
#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render {

class LineRestrictor {
  public:
    // Precondition: every exponent sum is at most kMaxDegree.
    explicit LineRestrictor(std::span<const algebra::CompiledTerm> terms);

    int degree() const { return degree_; }
    // f(origin + t·direction), exactly of degree `degree()` in layout (higher coefficients may
    // vanish for particular lines).
    RayPolynomial restrict_to(const Vec3& origin, const Vec3& direction) const;

  private:
    struct ZTerm {
        int ez;
        double coefficient;
    };
    struct YGroup {
        int ey;
        int max_ez;
        std::vector<ZTerm> z_terms;
    };
    struct XGroup {
        int ex;
        int max_yz;  // highest degree in y and z together
        std::vector<YGroup> y_groups;
    };
    std::vector<XGroup> x_groups_;
    int degree_ = -1;
    int max_exponent_ = 0;
};

}  // namespace locus::render
