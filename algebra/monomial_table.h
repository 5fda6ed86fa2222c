// Packed monomials stored once each and numbered in the order they arrive, found by hashing
// their words (open addressing, linear probing). F4's symbolic preprocessing (modular/f4.cpp)
// and the certification's dense reducer (groebner/detail/zero_reducer.h) number the monomials they
// meet with it, so that a term becomes an index into an array.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace locus::algebra {

class MonomialTable {
  public:
    explicit MonomialTable(std::size_t words)
        : words_(words), multipliers_(words), slots_(1024, Slot{kEmpty, 0}) {
        // Odd 64-bit constants, one a word (splitmix64 of the word's position).
        for (std::size_t w = 0; w < words; ++w) {
            std::uint64_t z = 0x9e3779b97f4a7c15ULL * (w + 1);
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            multipliers_[w] = (z ^ (z >> 31)) | 1;
        }
    }

    std::size_t size() const { return count_; }

    // Forgets every monomial (the indices start again from 0), keeping the memory.
    void clear() {
        count_ = 0;
        data_.clear();
        std::fill(slots_.begin(), slots_.end(), Slot{kEmpty, 0});
    }
    const std::uint64_t* at(std::uint32_t index) const { return data_.data() + index * words_; }

    // The hash of m: linear in its words (Σ m[w]·R_w mod 2⁶⁴), so that the hash of a product,
    // whose words are the sums of its factors' words (MonomialLayout::multiply), is the sum of
    // the factors' hashes: F4 hashes each row's multiplier once and adds the hashes of its
    // element's terms, instead of hashing every product word by word.
    std::uint64_t hash(const std::uint64_t* m) const {
        std::uint64_t h = 0;
        for (std::size_t w = 0; w < words_; ++w) {
            h += m[w] * multipliers_[w];
        }
        return h;
    }

    // The index of m, numbered next if it is new.
    std::uint32_t insert(const std::uint64_t* m) { return insert_hashed(m, hash(m)); }

    // insert(m) with hash(m) given (or the sum of the hashes of m's factors).
    std::uint32_t insert_hashed(const std::uint64_t* m, std::uint64_t h) {
        if (2 * (count_ + 1) > slots_.size()) {
            grow();
        }
        const std::uint64_t mixed = mix(h);
        const auto tag = static_cast<std::uint32_t>(mixed);
        std::size_t slot = mixed >> shift_;
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
        std::uint32_t tag;  // the low half of the monomial's mixed hash
    };
    // The linear hash spreads a word's low fields upwards only: fold the high half down and
    // multiply, and take the slot from the top bits of the product.
    static std::uint64_t mix(std::uint64_t h) { return (h ^ (h >> 32)) * 0x9e3779b97f4a7c15ULL; }
    // Monomials are a few words: a loop the compiler inlines beats a call to memcmp.
    bool equal(const std::uint64_t* a, const std::uint64_t* b) const {
        for (std::size_t w = 0; w < words_; ++w) {
            if (a[w] != b[w]) {
                return false;
            }
        }
        return true;
    }
    void grow() {
        std::vector<Slot> old(2 * slots_.size(), Slot{kEmpty, 0});
        old.swap(slots_);
        --shift_;
        for (const Slot& entry : old) {
            if (entry.index == kEmpty) {
                continue;
            }
            std::size_t slot = mix(hash(at(entry.index))) >> shift_;
            while (slots_[slot].index != kEmpty) {
                slot = (slot + 1) & (slots_.size() - 1);
            }
            slots_[slot] = entry;
        }
    }

    std::size_t words_;
    std::vector<std::uint64_t> multipliers_;
    std::vector<std::uint64_t> data_;
    std::vector<Slot> slots_;
    unsigned shift_ = 64 - 10;  // slots_.size() == 2^(64 − shift_)
    std::size_t count_ = 0;
};

}  // namespace locus::algebra
