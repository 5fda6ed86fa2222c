// Ideals over GF(p) given in the input: the `characteristic:` line of ideal files, msolve's
// format, printing in characteristic p, the reduced basis computed modulo the characteristic
// (against Singular's std in the same characteristic, captured below), and the independent
// check modulo p.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "algebra/error.h"
#include "algebra/groebner.h"
#include "algebra/groebner/verify.h"
#include "algebra/modular/modular_groebner.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

std::string refusal(IdealFile (*parse)(std::string_view), const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(PrimeField, TheCharacteristicLineIsReadAndChecked) {
    const IdealFile file = parse_ideal_file("vars: x,y\ncharacteristic: 32003\nx^2-1/2*y\n");
    EXPECT_EQ(file.characteristic, 32003u);
    EXPECT_EQ(parse_ideal_file("vars: x\nx\n").characteristic, 0u);
    EXPECT_EQ(parse_ideal_file("vars: x\ncharacteristic: 0\nx\n").characteristic, 0u);
    EXPECT_NE(refusal(parse_ideal_file, "vars: x\ncharacteristic: 6\nx\n")
                  .find("line 2, column 17: expected the characteristic: 0 or a prime below 2^31, "
                        "found 6, not a prime"),
              std::string::npos);
    EXPECT_NE(
        refusal(parse_ideal_file, "vars: x\ncharacteristic: 2147483648\nx\n").find("2^31 or more"),
        std::string::npos);
    EXPECT_NE(refusal(parse_ideal_file, "vars: x\ncharacteristic: 7x\nx\n").find("column 18"),
              std::string::npos);
    // 1/5 has no residue modulo 5; 1/5 modulo 7 is 3.
    EXPECT_NE(refusal(parse_ideal_file, "vars: x\ncharacteristic: 5\n\nx-1/5\n")
                  .find("line 4, column 1: expected coefficients whose denominators are not "
                        "divisible by the characteristic 5"),
              std::string::npos);
    EXPECT_EQ(refusal(parse_ideal_file, "vars: x\ncharacteristic: 7\nx-1/5\n"), "accepted");
}

TEST(PrimeField, MsolveFilesAreReadWithTheirPositions) {
    const IdealFile file = parse_msolve_file("x,y,z\n0\nx^2+y^2+z^2-1,\n  x*y\n  -z,x-1/2*y\n");
    EXPECT_EQ(file.characteristic, 0u);
    ASSERT_EQ(file.generators.size(), 3u);
    EXPECT_EQ(to_string(file.generators[1]), "x*y-z");
    EXPECT_EQ(file.generator_lines[2], 5u);
    EXPECT_EQ(file.ring->order().kind(), MonomialOrder::Kind::grevlex);
    EXPECT_EQ(parse_msolve_file("a,b\n65521\na-b\n").characteristic, 65521u);
    EXPECT_TRUE(looks_like_msolve("x,y\n0\nx-y\n"));
    EXPECT_FALSE(looks_like_msolve("vars: x,y\nx-y\n"));
    EXPECT_NE(refusal(parse_msolve_file, "").find("line 1, column 1: expected the variables"),
              std::string::npos);
    EXPECT_NE(refusal(parse_msolve_file, "x,y\n").find("expected the characteristic"),
              std::string::npos);
    EXPECT_NE(refusal(parse_msolve_file, "x,y\n0\n").find("a polynomial after the characteristic"),
              std::string::npos);
    EXPECT_NE(
        refusal(parse_msolve_file, "x,y\n0\nx,\n").find("line 3, column 3: expected a polynomial"),
        std::string::npos);
    EXPECT_NE(refusal(parse_msolve_file, "x,y\n0\nx,,y\n").find("line 3, column 3"),
              std::string::npos);
    EXPECT_NE(refusal(parse_msolve_file, "x,y\n0\nx,\n y+w\n").find("line 4, column 4"),
              std::string::npos);
    EXPECT_NE(refusal(parse_msolve_file, "x,x\n0\nx\n").find("line 1"), std::string::npos);
    EXPECT_NE(refusal(parse_msolve_file, "x,y\n9\nx\n").find("9, not a prime"), std::string::npos);
}

TEST(PrimeField, RingsAndFilesSayTheCharacteristic) {
    const IdealFile file = parse_ideal_file("vars: x,y\ncharacteristic: 101\nx^2+100*y\nx*y-1\n");
    const std::string singular =
        format_polynomials(file.generators, *file.ring, OutputFormat::singular, "G", 101);
    EXPECT_EQ(singular.substr(0, singular.find('\n')), "ring r = 101, (x,y), dp;");
    const std::string m2 =
        format_polynomials(file.generators, *file.ring, OutputFormat::macaulay2, "G", 101);
    EXPECT_EQ(m2.substr(0, 10), "R = ZZ/101");
    // msolve's format and the ideal file read back to the same generators and characteristic.
    for (const std::string& text :
         {format_polynomials(file.generators, *file.ring, OutputFormat::msolve, "G", 101),
          to_ideal_file(file.generators, *file.ring, 101)}) {
        const IdealFile back =
            text.starts_with("vars:") ? parse_ideal_file(text) : parse_msolve_file(text);
        EXPECT_EQ(back.characteristic, 101u) << text;
        ASSERT_EQ(back.generators.size(), 2u) << text;
        EXPECT_EQ(to_string(back.generators[0]), "x^2+100*y");
    }
    EXPECT_EQ(format_polynomials({}, *file.ring, OutputFormat::msolve, "G", 101), "x,y\n101\n0\n");
}

// The residues of f's coefficients in [0, p), for comparing with Singular's symmetric ones.
std::string residue_string(const Polynomial& f, long p) {
    std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        long n = std::stol(f.coefficient(i).to_string());  // Singular prints integers
        terms.push_back({Rational(((n % p) + p) % p), f.exponents(i)});
    }
    return to_string(Polynomial::from_terms(f.ring(), std::move(terms)));
}

void expect_basis_as_singular(const std::string& ideal_text, long p,
                              const std::vector<std::string>& singular_basis) {
    const IdealFile file = parse_ideal_file(ideal_text);
    const std::vector<Polynomial> basis =
        groebner_modulo(file.generators, static_cast<std::uint32_t>(p));
    std::vector<std::string> ours, theirs;
    for (const auto& g : basis) {
        ours.push_back(to_string(g));
    }
    for (const auto& s : singular_basis) {
        theirs.push_back(residue_string(parse_polynomial(s, file.ring), p));
    }
    std::sort(ours.begin(), ours.end());
    std::sort(theirs.begin(), theirs.end());
    EXPECT_EQ(ours, theirs);
    const BasisCheck check =
        check_groebner_basis_modulo(basis, file.generators, static_cast<std::uint32_t>(p));
    EXPECT_TRUE(check.ok) << check.failure;
    EXPECT_TRUE(is_reduced(basis));
}

TEST(PrimeField, BasesAgreeWithSingularInTheSameCharacteristic) {
    // Captured from Singular 4.3.1: ring r = 101, (x0,x1,x2,x3), dp; option(redSB); std(I).
    expect_basis_as_singular(
        "vars: x0,x1,x2,x3\ncharacteristic: 101\nx0+2*x1+2*x2+2*x3-1\n"
        "x0^2+2*x1^2+2*x2^2+2*x3^2-x0\n2*x0*x1+2*x1*x2+2*x2*x3-x1\nx1^2+2*x0*x2+2*x1*x3-x2\n",
        101,
        {"x0+2*x1+2*x2+2*x3-1", "x2^2+2*x1*x3+19*x2*x3-25*x3^2-29*x1-15*x2+42*x3",
         "x1*x2-2*x1*x3+40*x2*x3+11*x3^2-36*x1-43*x2+30*x3",
         "x1^2+2*x1*x3+30*x2*x3+45*x3^2+43*x1-29*x2-15*x3",
         "x2*x3^2+46*x3^3+28*x1*x3+16*x2*x3+7*x3^2-43*x1-38*x2+15*x3",
         "x1*x3^2-34*x3^3-45*x1*x3-43*x2*x3+45*x3^2+14*x1-15*x2",
         "x3^4-36*x3^3+26*x1*x3+47*x2*x3-30*x3^2+37*x1-22*x2-x3"});
    // ring r = 7, (x0,...,x4), lp: katsura-5 under lex, modulo 7.
    expect_basis_as_singular(
        "vars: x0,x1,x2,x3,x4\norder: lex\ncharacteristic: 7\n"
        "x0+2*x1+2*x2+2*x3+2*x4-1\nx0^2+2*x1^2+2*x2^2+2*x3^2+2*x4^2-x0\n"
        "2*x0*x1+2*x1*x2+2*x2*x3+2*x3*x4-x1\nx1^2+2*x0*x2+2*x1*x3+2*x2*x4-x2\n"
        "2*x1*x2+2*x0*x3+2*x1*x4-x3\n",
        7,
        {"x4^14-x4^13-2*x4^12+x4^11-3*x4^10-x4^9+x4^8-2*x4^7-x4^6+x4^5-3*x4^4+3*x4^3-3*x4^2-x4",
         "x3+3*x4^13-2*x4^12+x4^11-x4^9-x4^7+3*x4^6-2*x4^5-2*x4^4+2*x4^3-2*x4",
         "x2*x4+2*x2+x4^12+x4^11-x4^10+x4^9+x4^8+2*x4^7-x4^6-x4^5+3*x4^4+2*x4^3+3*x4^2+3*x4",
         "x2^2-3*x2-x4^13+2*x4^11-2*x4^10-x4^9-3*x4^6-x4^5-2*x4^4+2*x4^3+2*x4^2-3*x4",
         "x1-2*x4^13+2*x4^12-x4^11+3*x4^8+x4^6+2*x4^5-x4^4+2*x4^3+2*x4^2-x4",
         "x0+2*x2-2*x4^13+2*x4^9+x4^8+2*x4^7-x4^6-x4^4-x4^3+3*x4^2+x4-1"});
}

TEST(PrimeField, TheCheckModuloPRejectsWrongBases) {
    const IdealFile file =
        parse_ideal_file("vars: x,y,z\ncharacteristic: 32003\nx^2+y^2+z^2-1\nx*y-z\nx-y+z^3\n");
    std::vector<Polynomial> basis = groebner_modulo(file.generators, 32003);
    ASSERT_TRUE(check_groebner_basis_modulo(basis, file.generators, 32003).ok);
    // The same basis is not one modulo another prime, and not without its last element, nor
    // with a coefficient changed.
    EXPECT_FALSE(check_groebner_basis_modulo(basis, file.generators, 32009).ok);
    std::vector<Polynomial> shorter(basis.begin(), basis.end() - 1);
    EXPECT_FALSE(check_groebner_basis_modulo(shorter, file.generators, 32003).ok);
    std::vector<Polynomial> changed = basis;
    changed.back() += Polynomial::constant(file.ring, Rational(1));
    EXPECT_FALSE(check_groebner_basis_modulo(changed, file.generators, 32003).ok);
}

// F4's row reduction sums products unreduced in 64 bits when no sum can overflow (p = 65 521
// on any matrix; 23-bit primes on matrices below 2¹⁸ rows) and keeps entries below 2p²
// otherwise (31-bit primes). Katsura-6 and cyclic-6 on both sides of that bound, each basis
// checked modulo its prime by the division algorithm (no F4 code), reduced, and with the
// leading monomials of the basis over Q (these primes are lucky for both).
TEST(PrimeField, RowReductionIsRightWithAndWithoutLazySums) {
    const char* const ideals[] = {
        "vars: x0,x1,x2,x3,x4,x5\n"
        "x0+2*x1+2*x2+2*x3+2*x4+2*x5-1\nx0^2+2*x1^2+2*x2^2+2*x3^2+2*x4^2+2*x5^2-x0\n"
        "2*x0*x1+2*x1*x2+2*x2*x3+2*x3*x4+2*x4*x5-x1\nx1^2+2*x0*x2+2*x1*x3+2*x2*x4+2*x3*x5-x2\n"
        "2*x1*x2+2*x0*x3+2*x1*x4+2*x2*x5-x3\nx2^2+2*x1*x3+2*x0*x4+2*x1*x5-x4\n",
        "vars: a,b,c,d,e,f\na+b+c+d+e+f\na*b+b*c+c*d+d*e+e*f+f*a\n"
        "a*b*c+b*c*d+c*d*e+d*e*f+e*f*a+f*a*b\na*b*c*d+b*c*d*e+c*d*e*f+d*e*f*a+e*f*a*b+f*a*b*c\n"
        "a*b*c*d*e+b*c*d*e*f+c*d*e*f*a+d*e*f*a*b+e*f*a*b*c+f*a*b*c*d\na*b*c*d*e*f-1\n"};
    for (const char* text : ideals) {
        const IdealFile file = parse_ideal_file(text);
        const GroebnerAnswer over_q = groebner(file.generators, GroebnerRequest{});
        ASSERT_EQ(over_q.outcome, GroebnerOutcome::complete);
        auto leading_exponents = [](const std::vector<Polynomial>& basis) {
            std::vector<std::vector<std::uint32_t>> out;
            for (const Polynomial& g : basis) {
                out.push_back(g.exponents(0));
            }
            std::sort(out.begin(), out.end());
            return out;
        };
        for (const std::uint32_t p : {65521u, 8388593u, 2147483647u}) {
            const std::vector<Polynomial> basis = groebner_modulo(file.generators, p);
            const BasisCheck check = check_groebner_basis_modulo(basis, file.generators, p);
            EXPECT_TRUE(check.ok) << "p = " << p << ": " << check.failure;
            EXPECT_TRUE(is_reduced(basis)) << "p = " << p;
            EXPECT_EQ(leading_exponents(basis), leading_exponents(over_q.basis)) << "p = " << p;
        }
    }
    // Inputs nobody chose: 60 random small ideals under six orders (tests/support) and 12
    // ideals of five random dense quadrics in five variables (every monomial of degree ≤ 2,
    // coefficients in [−9, 9]), modulo both primes, each basis checked by the division
    // algorithm modulo p. Their matrices (up to about a hundred rows) are too small for a wrong
    // bound to overflow — forcing lazy sums for 31-bit primes fails only the cases above — so
    // these check the rest of the reduction (shared coefficients, the unrolled update).
    std::vector<IdealFile> random_ideals;
    for (int seed = 0; seed < test::seed_count(60); ++seed) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed) + 4000);
        random_ideals.push_back(test::random_ideal(rng, seed));
    }
    std::vector<std::vector<std::uint32_t>> quadratic;  // exponents of degree ≤ 2 in 5 variables
    for (std::uint32_t i = 0; i <= 5; ++i) {
        for (std::uint32_t j = i; j <= 5; ++j) {
            std::vector<std::uint32_t> e(5, 0);
            for (const std::uint32_t v : {i, j}) {
                if (v < 5) {
                    ++e[v];
                }
            }
            quadratic.push_back(e);
        }
    }
    for (int seed = 0; seed < test::seed_count(12); ++seed) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed) + 5000);
        std::uniform_int_distribution<long> coefficient(-9, 9);
        IdealFile dense;
        dense.ring = PolyRing::make({"a", "b", "c", "d", "e"}, MonomialOrder::grevlex(5));
        for (int k = 0; k < 5; ++k) {
            std::vector<std::pair<Rational, std::vector<std::uint32_t>>> terms;
            for (const std::vector<std::uint32_t>& e : quadratic) {
                terms.emplace_back(Rational(coefficient(rng)), e);
            }
            dense.generators.push_back(Polynomial::from_terms(dense.ring, std::move(terms)));
        }
        random_ideals.push_back(std::move(dense));
    }
    for (std::size_t seed = 0; seed < random_ideals.size(); ++seed) {
        const IdealFile& ideal = random_ideals[seed];
        for (const std::uint32_t p : {65521u, 2147483647u}) {
            const std::vector<Polynomial> basis = groebner_modulo(ideal.generators, p);
            const BasisCheck check = check_groebner_basis_modulo(basis, ideal.generators, p);
            EXPECT_TRUE(check.ok) << "seed " << seed << ", p = " << p << ": " << check.failure;
            EXPECT_TRUE(is_reduced(basis)) << "seed " << seed << ", p = " << p;
        }
    }
}

}  // namespace
}  // namespace locus::algebra
