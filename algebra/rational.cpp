#include "algebra/rational.h"

#include <flint/fmpz.h>

#include <cctype>
#include <memory>

namespace locus::algebra {
namespace {

std::string fmpz_string(const fmpz* v) {
    // fmpz_get_str allocates with flint_malloc; free it the same way.
    std::unique_ptr<char, void (*)(void*)> s(fmpz_get_str(nullptr, 10, v), flint_free);
    return std::string(s.get());
}

}  // namespace

std::string Integer::to_string() const {
    return fmpz_string(v_);
}

Rational::Rational(long numerator, unsigned long denominator) {
    fmpq_init(v_);
    fmpq_set_si(v_, numerator, denominator);
}

Rational::Rational(const Integer& numerator, const Integer& denominator) {
    fmpq_init(v_);
    fmpq_set_fmpz_frac(v_, numerator.get(), denominator.get());
}

std::string Rational::to_string() const {
    std::string s = fmpz_string(fmpq_numref(v_));
    if (!fmpz_is_one(fmpq_denref(v_))) {
        s += '/';
        s += fmpz_string(fmpq_denref(v_));
    }
    return s;
}

bool Rational::from_literal(std::string_view text, Rational& out) {
    auto all_digits = [](std::string_view s) {
        if (s.empty()) {
            return false;
        }
        for (char c : s) {
            if (!std::isdigit(static_cast<unsigned char>(c))) {
                return false;
            }
        }
        return true;
    };
    const auto slash = text.find('/');
    // A decimal exponent: the mantissa (an integer or a decimal, not a fraction) times 10^e.
    const auto e = text.find_first_of("eE");
    if (e != std::string_view::npos && slash == std::string_view::npos) {
        std::string_view exponent = text.substr(e + 1);
        const bool negative = !exponent.empty() && exponent.front() == '-';
        if (!exponent.empty() && (exponent.front() == '-' || exponent.front() == '+')) {
            exponent.remove_prefix(1);
        }
        // Leading zeros do not make an exponent large.
        while (exponent.size() > 1 && exponent.front() == '0') {
            exponent.remove_prefix(1);
        }
        Rational mantissa;
        // (Four digits are past kMaxDecimalExponent already, and within std::stoi's range.)
        if (!all_digits(exponent) || exponent.size() > 4 ||
            std::stoi(std::string(exponent)) > kMaxDecimalExponent ||
            !from_literal(text.substr(0, e), mantissa)) {
            return false;
        }
        const int power = std::stoi(std::string(exponent));
        Integer scale;
        fmpz_set_ui(scale.get(), 10);
        fmpz_pow_ui(scale.get(), scale.get(), static_cast<ulong>(power));
        out = negative ? mantissa / Rational(scale) : mantissa * Rational(scale);
        return true;
    }
    const auto dot = text.find('.');
    Integer num, den(1);
    if (slash != std::string_view::npos) {
        const auto a = text.substr(0, slash), b = text.substr(slash + 1);
        if (!all_digits(a) || !all_digits(b)) {
            return false;
        }
        fmpz_set_str(num.get(), std::string(a).c_str(), 10);
        fmpz_set_str(den.get(), std::string(b).c_str(), 10);
        if (den.is_zero()) {
            return false;
        }
    } else if (dot != std::string_view::npos) {
        const auto a = text.substr(0, dot), b = text.substr(dot + 1);
        if ((a.empty() && b.empty()) || (!a.empty() && !all_digits(a)) ||
            (!b.empty() && !all_digits(b))) {
            return false;
        }
        const std::string digits = std::string(a) + std::string(b);
        fmpz_set_str(num.get(), digits.c_str(), 10);
        fmpz_set_ui(den.get(), 10);
        fmpz_pow_ui(den.get(), den.get(), b.size());
    } else {
        if (!all_digits(text)) {
            return false;
        }
        fmpz_set_str(num.get(), std::string(text).c_str(), 10);
    }
    out = Rational(num, den);
    return true;
}

}  // namespace locus::algebra
