#include "algebra/groebner/detail/zero_reducer.h"

namespace locus::algebra::detail {

ZeroReducer::ZeroReducer(const MonomialLayout& layout, const std::vector<BasisElement>& basis)
    : layout_(layout), basis_(basis) {
    if (ResidueZeroReducer::initial_lanes(basis) <= ResidueZeroReducer::kMostLanes) {
        residue_ = std::make_unique<ResidueZeroReducer>(layout, basis);
    }
}

ZeroReducer::~ZeroReducer() = default;

void ZeroReducer::set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) {
    deadline_ = deadline;
    if (residue_) {
        residue_->set_deadline(deadline);
    }
    if (exact_) {
        exact_->set_deadline(deadline);
    }
}

ExactZeroReducer& ZeroReducer::exact() {
    if (!exact_) {
        exact_ = std::make_unique<ExactZeroReducer>(layout_, basis_);
        exact_->set_deadline(deadline_);
    }
    return *exact_;
}

void ZeroReducer::reduce_together(std::span<const Job> jobs, std::span<bool> zero,
                                  std::span<ReductionCounts> counts) {
    std::vector<ResidueZeroReducer::Verdict> verdicts(jobs.size(),
                                                      ResidueZeroReducer::Verdict::too_wide);
    if (residue_) {
        residue_->reduce_together(jobs, verdicts, counts);
    }
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        if (verdicts[k] != ResidueZeroReducer::Verdict::too_wide) {
            zero[k] = verdicts[k] == ResidueZeroReducer::Verdict::zero;
            continue;
        }
        if (residue_) {
            residue_statistics_ = residue_->statistics();
            residue_.reset();
        }
        const Job& job = jobs[k];
        zero[k] = job.polynomial != nullptr ? exact().reduces_to_zero(*job.polynomial, counts[k])
                                            : exact().s_polynomial_reduces_to_zero(
                                                  job.first, job.second, job.lcm, counts[k]);
    }
}

CertificationWork ZeroReducer::statistics() const {
    const ResidueZeroReducer::Statistics r =
        residue_ ? residue_->statistics() : residue_statistics_;
    CertificationWork work;
    work.lanes = r.lanes;  // 0 when the residues were never used
    work.lane_restarts = r.restarts;
    work.rebuilds = r.rebuilds;
    work.reducer_terms = r.reducer_terms;
    work.lane_terms = r.lane_terms;
    work.row_terms = r.row_terms;
    work.columns = r.columns;
    work.exact_fallback = exact_ != nullptr;
    return work;
}

}  // namespace locus::algebra::detail
