// Packed monomials stored once each and numbered in the order they arrive, found by hashing
// their words (open addressing, linear probing). F4's symbolic preprocessing (modular/f4.cpp)
// and the certification's dense reducer (groebner/zero_reducer.h) number the monomials they
// meet with it, so that a term becomes an index into an array.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace locus::algebra {

class MonomialTable {
  public:
    explicit MonomialTable(std::size_t words) : words_(words), slots_(1024, kEmpty) {}

    std::size_t size() const { return count_; }
    const std::uint64_t* at(std::uint32_t index) const { return data_.data() + index * words_; }

    // The index of m, numbered next if it is new.
    std::uint32_t insert(const std::uint64_t* m) {
        if (2 * (count_ + 1) > slots_.size()) {
            grow();
        }
        std::size_t slot = hash(m) & (slots_.size() - 1);
        while (slots_[slot] != kEmpty) {
            if (std::memcmp(at(slots_[slot]), m, words_ * sizeof(std::uint64_t)) == 0) {
                return slots_[slot];
            }
            slot = (slot + 1) & (slots_.size() - 1);
        }
        const auto index = static_cast<std::uint32_t>(count_++);
        data_.insert(data_.end(), m, m + words_);
        slots_[slot] = index;
        return index;
    }

  private:
    static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
    std::uint64_t hash(const std::uint64_t* m) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (std::size_t w = 0; w < words_; ++w) {
            h = (h ^ m[w]) * 0xff51afd7ed558ccdULL;
            h ^= h >> 32;
        }
        return h;
    }
    void grow() {
        std::vector<std::uint32_t> old(2 * slots_.size(), kEmpty);
        old.swap(slots_);
        for (std::uint32_t index = 0; index < count_; ++index) {
            std::size_t slot = hash(at(index)) & (slots_.size() - 1);
            while (slots_[slot] != kEmpty) {
                slot = (slot + 1) & (slots_.size() - 1);
            }
            slots_[slot] = index;
        }
    }

    std::size_t words_;
    std::vector<std::uint64_t> data_;
    std::vector<std::uint32_t> slots_;
    std::size_t count_ = 0;
};

}  // namespace locus::algebra
