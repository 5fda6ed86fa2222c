// Exact scalars: RAII value types over FLINT's fmpz (Integer) and fmpq (Rational).
//
// fmpz keeps small values inline in one machine word and switches to GMP only when needed, so
// a vector<Integer> costs one word per small coefficient. Moves swap with a fresh zero (no
// allocation), so containers of these types move cheaply. Rationals are always canonical
// (lowest terms, positive denominator), as fmpq guarantees.
#pragma once

#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <string>
#include <string_view>
#include <utility>

namespace locus::algebra {

class Integer {
  public:
    Integer() { fmpz_init(v_); }
    Integer(long value) { fmpz_init_set_si(v_, value); }  // NOLINT: implicit from integers
    Integer(const Integer& o) { fmpz_init_set(v_, o.v_); }
    Integer(Integer&& o) noexcept {
        fmpz_init(v_);
        fmpz_swap(v_, o.v_);
    }
    Integer& operator=(const Integer& o) {
        fmpz_set(v_, o.v_);
        return *this;
    }
    Integer& operator=(Integer&& o) noexcept {
        fmpz_swap(v_, o.v_);
        return *this;
    }
    ~Integer() { fmpz_clear(v_); }

    fmpz* get() { return v_; }
    const fmpz* get() const { return v_; }

    bool is_zero() const { return fmpz_is_zero(v_); }
    bool is_one() const { return fmpz_is_one(v_); }
    int sign() const { return fmpz_sgn(v_); }
    std::string to_string() const;

    friend bool operator==(const Integer& a, const Integer& b) { return fmpz_equal(a.v_, b.v_); }
    friend Integer operator*(const Integer& a, const Integer& b) {
        Integer r;
        fmpz_mul(r.v_, a.v_, b.v_);
        return r;
    }
    friend Integer operator-(const Integer& a) {
        Integer r;
        fmpz_neg(r.v_, a.v_);
        return r;
    }

  private:
    fmpz_t v_;
};

class Rational {
  public:
    Rational() { fmpq_init(v_); }
    Rational(long value) {  // NOLINT: implicit from integers
        fmpq_init(v_);
        fmpq_set_si(v_, value, 1);
    }
    Rational(long numerator, unsigned long denominator);  // canonicalizes; denominator != 0
    explicit Rational(const Integer& value) {
        fmpq_init(v_);
        fmpz_set(fmpq_numref(v_), value.get());
    }
    Rational(const Integer& numerator, const Integer& denominator);  // canonicalizes
    Rational(const Rational& o) {
        fmpq_init(v_);
        fmpq_set(v_, o.v_);
    }
    Rational(Rational&& o) noexcept {
        fmpq_init(v_);
        fmpq_swap(v_, o.v_);
    }
    Rational& operator=(const Rational& o) {
        fmpq_set(v_, o.v_);
        return *this;
    }
    Rational& operator=(Rational&& o) noexcept {
        fmpq_swap(v_, o.v_);
        return *this;
    }
    ~Rational() { fmpq_clear(v_); }

    fmpq* get() { return v_; }
    const fmpq* get() const { return v_; }
    const fmpz* numerator() const { return fmpq_numref(v_); }
    const fmpz* denominator() const { return fmpq_denref(v_); }

    bool is_zero() const { return fmpq_is_zero(v_); }
    bool is_one() const { return fmpq_is_one(v_); }
    bool is_integer() const { return fmpz_is_one(fmpq_denref(v_)); }
    int sign() const { return fmpq_sgn(v_); }
    // "a" or "a/b" in lowest terms.
    std::string to_string() const;
    // Exact value of a decimal or fraction literal such as "12", "3/4", "0.125" or "1.5e-3"
    // (a decimal with an exponent: 3/2000); returns false when `text` is not of that form or
    // its exponent exceeds kMaxDecimalExponent in size (1e999999999 would be a number of three
    // billion digits).
    static bool from_literal(std::string_view text, Rational& out);
    static constexpr int kMaxDecimalExponent = 999;

    Rational& operator+=(const Rational& o) {
        fmpq_add(v_, v_, o.v_);
        return *this;
    }
    Rational& operator-=(const Rational& o) {
        fmpq_sub(v_, v_, o.v_);
        return *this;
    }
    Rational& operator*=(const Rational& o) {
        fmpq_mul(v_, v_, o.v_);
        return *this;
    }
    // Precondition: o != 0.
    Rational& operator/=(const Rational& o) {
        fmpq_div(v_, v_, o.v_);
        return *this;
    }
    friend Rational operator+(Rational a, const Rational& b) { return a += b; }
    friend Rational operator-(Rational a, const Rational& b) { return a -= b; }
    friend Rational operator*(Rational a, const Rational& b) { return a *= b; }
    friend Rational operator/(Rational a, const Rational& b) { return a /= b; }
    friend Rational operator-(const Rational& a) {
        Rational r;
        fmpq_neg(r.v_, a.v_);
        return r;
    }
    friend bool operator==(const Rational& a, const Rational& b) { return fmpq_equal(a.v_, b.v_); }
    friend bool operator<(const Rational& a, const Rational& b) { return fmpq_cmp(a.v_, b.v_) < 0; }

  private:
    fmpq_t v_;
};

}  // namespace locus::algebra
