// One of three builds of the same kernels — AVX-512F, AVX2 and portable code — for the
// processor at hand: the best it runs, chosen at first use, and any it runs selectable by name
// so that the tests can check each against the others. `Kernels` is a struct of function
// pointers with a `name`. Internal to algebra/.
#pragma once

#include <array>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace locus::algebra::detail {

template <class Kernels>
class KernelChoice {
  public:
    KernelChoice(const Kernels& portable, const Kernels& avx2, const Kernels& avx512)
        : builds_{&portable, &avx2, &avx512}, active_(best()) {}

    const Kernels& get() const { return *active_.load(std::memory_order_relaxed); }

    // "portable", then "avx2" and "avx512" where the processor runs them.
    std::vector<std::string> supported() const {
        std::vector<std::string> names;
        for (std::size_t i = 0; i < builds_.size(); ++i) {
            if (runs(i)) {
                names.emplace_back(builds_[i]->name);
            }
        }
        return names;
    }

    // Throws std::invalid_argument when the processor does not run that build.
    void select(const std::string& name) {
        for (std::size_t i = 0; i < builds_.size(); ++i) {
            if (name == builds_[i]->name && runs(i)) {
                active_.store(builds_[i], std::memory_order_relaxed);
                return;
            }
        }
        throw std::invalid_argument("kernels not supported here: " + name);
    }

  private:
    static bool runs(std::size_t build) {
        __builtin_cpu_init();
        switch (build) {
        case 1:
            return __builtin_cpu_supports("avx2") != 0;
        case 2:
            return __builtin_cpu_supports("avx512f") != 0;
        default:
            return true;
        }
    }
    const Kernels* best() const {
        for (std::size_t i = builds_.size(); i-- > 0;) {
            if (runs(i)) {
                return builds_[i];
            }
        }
        return builds_[0];
    }

    std::array<const Kernels*, 3> builds_;
    std::atomic<const Kernels*> active_;
};

}  // namespace locus::algebra::detail
