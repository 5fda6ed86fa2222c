// LOCUS_ASSERT(condition): an internal invariant (canonical form of a polynomial, clear guard
// bits of a packed monomial, a sorted basis), checked in debug builds and compiled out when
// NDEBUG is defined (the release presets). A failure is a bug in locus, not in the input: it
// names the condition and the place and aborts, so that the sanitizer builds stop at the first
// broken invariant rather than at its consequence.
#pragma once

namespace locus::detail {

[[noreturn]] void assertion_failed(const char* condition, const char* file, int line);

}  // namespace locus::detail

#ifdef NDEBUG
#define LOCUS_ASSERT(condition) static_cast<void>(0)
#else
#define LOCUS_ASSERT(condition)         \
    ((condition) ? static_cast<void>(0) \
                 : ::locus::detail::assertion_failed(#condition, __FILE__, __LINE__))
#endif
