#include "implicit/detail/modular_lifting.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

namespace locus::implicit::detail {

NormalizedLifting::NormalizedLifting(std::size_t size, std::size_t pivot)
    : pivot_(pivot), residues_(size), current_(size) {}

bool NormalizedLifting::add(const std::vector<ulong>& image, ulong p) {
    const ulong pinv = n_preinvert_limb(p);
    const ulong scale = n_invmod(image[pivot_], p);
    for (std::size_t j = 0; j < residues_.size(); ++j) {
        const ulong v = n_mulmod2_preinv(image[j], scale, p, pinv);
        fmpz_CRT_ui(residues_[j].get(), residues_[j].get(), modulus_.get(), v, p, 0);
    }
    fmpz_mul_ui(modulus_.get(), modulus_.get(), p);
    ++primes_;
    bool reconstructed = true;
    for (std::size_t j = 0; j < residues_.size() && reconstructed; ++j) {
        reconstructed =
            fmpq_reconstruct_fmpz(current_[j].get(), residues_[j].get(), modulus_.get()) != 0;
    }
    if (!reconstructed || current_ != previous_) {
        previous_ = current_;
        return false;
    }
    return true;
}

}  // namespace locus::implicit::detail
