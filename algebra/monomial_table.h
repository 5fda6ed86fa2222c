// Packed monomials stored once each and numbered in the order they arrive, found by hashing
// their words (open addressing, linear probing). F4's symbolic preprocessing (modular/f4.cpp)
// and the certification's dense reducer (groebner/zero_reducer.h) number the monomials they
// meet with it, so that a term becomes an index into an array.
#pragma once

#include <cstdint>
#include <vector>

namespace locus::algebra {

class MonomialTable {
  public:
    explicit MonomialTable(std::size_t words) : words_(words), slots_(1024, Slot{kEmpty, 0}) {}

    std::size_t size() const { return count_; }
    const std::uint64_t* at(std::uint32_t index) const { return data_.data() + index * words_; }

    // The index of m, numbered next if it is new.
    std::uint32_t insert(const std::uint64_t* m) {
        if (2 * (count_ + 1) > slots_.size()) {
            grow();
        }
        const std::uint64_t h = hash(m);
        const auto tag = static_cast<std::uint32_t>(h >> 32);
        std::size_t slot = h & (slots_.size() - 1);
        // A slot keeps its monomial's hash tag beside its index: most probes that meet another
        // monomial are settled by the tag, without reading the monomial's words.
        while (slots_[slot].index != kEmpty) {
            if (slots_[slot].tag == tag && equal(at(slots_[slot].index), m)) {
                return slots_[slot].index;
            }
            slot = (slot + 1) & (slots_.size() - 1);
        }
        const auto index = static_cast<std::uint32_t>(count_++);
        data_.insert(data_.end(), m, m + words_);
        slots_[slot] = {index, tag};
        return index;
    }

  private:
    static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
    struct Slot {
        std::uint32_t index;
        std::uint32_t tag;  // the high half of the monomial's hash
    };
    // Monomials are a few words: a loop the compiler inlines beats a call to memcmp.
    bool equal(const std::uint64_t* a, const std::uint64_t* b) const {
        for (std::size_t w = 0; w < words_; ++w) {
            if (a[w] != b[w]) {
                return false;
            }
        }
        return true;
    }
    std::uint64_t hash(const std::uint64_t* m) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (std::size_t w = 0; w < words_; ++w) {
            h = (h ^ m[w]) * 0xff51afd7ed558ccdULL;
            h ^= h >> 32;
        }
        return h;
    }
    void grow() {
        std::vector<Slot> old(2 * slots_.size(), Slot{kEmpty, 0});
        old.swap(slots_);
        for (const Slot& entry : old) {
            if (entry.index == kEmpty) {
                continue;
            }
            std::size_t slot = hash(at(entry.index)) & (slots_.size() - 1);
            while (slots_[slot].index != kEmpty) {
                slot = (slot + 1) & (slots_.size() - 1);
            }
            slots_[slot] = entry;
        }
    }

    std::size_t words_;
    std::vector<std::uint64_t> data_;
    std::vector<Slot> slots_;
    std::size_t count_ = 0;
};

}  // namespace locus::algebra
