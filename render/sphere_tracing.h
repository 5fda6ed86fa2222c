// Sphere tracing (Hart, "Sphere tracing: a geometric method for the antialiased ray tracing of
// implicit surfaces", 1996) along one ray, in two flavours that differ in what they know:
//
//  * gradient: steps by |f(p)| / |∇f(p)|, the first-order distance *estimate*. It is cheap and
//    good far from the surface, but it is not a bound: near high curvature, thin features or
//    singular points it can step past a root (it catches a sign change and bisects back, but
//    two roots jumped over together are lost). An estimate (sdf::DistanceKind::estimate).
//  * lipschitz: steps on the restriction F(t) by |F(t)| / L, where L bounds |F'| on the
//    window [t, t + h] from the Taylor coefficients of F at t (|F'(t+s)| ≤ Σ j|b_j| h^(j−1)).
//    The step never passes a root (a bound, sdf::DistanceKind::bound); the window adapts so that L
//    stays tight, which makes convergence to a simple root quadratic.
#pragma once

#include "algebra/compiled.h"
#include "render/root_finder.h"
#include "render/vec3.h"

namespace locus::render {

// `tolerance` is a distance in world units below which |f|/|∇f| counts as on the surface.
RootResult sphere_trace_gradient(const algebra::CompiledPolynomial& f, const Ray& ray,
                                 Interval interval, double tolerance);

// `t_tolerance`: a step shorter than this ends the march with a hit.
RootResult sphere_trace_lipschitz(const RayPolynomial& restriction, Interval interval,
                                  double t_tolerance);

}  // namespace locus::render
