// Internal to the Gröbner code: decides whether integer polynomials reduce to zero by a basis
// that does not change, for the certification of multi-modular results (verify.h).
//
// Both reducers behind it make the same fraction-free steps on the same integers (the steps of
// Reducer, reduction.h); they differ in how they hold the integers. ResidueZeroReducer holds
// them as residues modulo word primes with rigorous size bounds, a vector multiply-add per
// term; ExactZeroReducer as GMP integers. The residues are used unless the integers need more
// than ResidueZeroReducer::kMostLanes primes (coefficients of thousands of digits, where
// setting up the lanes costs more than the few steps such bases take); a reduction that
// outgrows them moves this reducer to GMP integers for good.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "algebra/groebner/detail/exact_zero_reducer.h"
#include "algebra/groebner/detail/residue_zero_reducer.h"
#include "algebra/groebner/verify.h"

namespace locus::algebra::detail {

class ZeroReducer {
  public:
    // `basis` is read, not copied: it must outlive the reducer and not change.
    ZeroReducer(const MonomialLayout& layout, const std::vector<BasisElement>& basis);
    ~ZeroReducer();
    ZeroReducer(const ZeroReducer&) = delete;
    ZeroReducer& operator=(const ZeroReducer&) = delete;

    // Throws ReductionInterrupted once the deadline has passed (checked every 16 steps).
    void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline);

    // Whether each job reduces to zero (zero[k] for jobs[k]), reduced together while on
    // residues (ResidueZeroReducer::reduce_together), one after another on GMP integers.
    using Job = ResidueZeroReducer::Job;
    // The jobs the certification reduces together: a slot each (residue_lanes.h).
    static constexpr std::size_t kGroup = lanes::kSlots;
    void reduce_together(std::span<const Job> jobs, std::span<bool> zero,
                         std::span<ReductionCounts> counts);

    // The most lanes the residues used (0 on GMP integers only), restarts, rebuilds, and whether
    // some reductions ran on GMP integers; reduction_steps are counted by the caller
    // (ReductionCounts).
    CertificationWork statistics() const;

  private:
    ExactZeroReducer& exact();

    const MonomialLayout& layout_;
    const std::vector<BasisElement>& basis_;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::unique_ptr<ResidueZeroReducer> residue_;        // null once the lanes ran out
    std::unique_ptr<ExactZeroReducer> exact_;            // made when first needed
    ResidueZeroReducer::Statistics residue_statistics_;  // of residue_, kept when it goes
};

}  // namespace locus::algebra::detail
