// prove_ideal_equality: that a certified basis generates no more than the input's ideal. The
// oracle is Buchberger's algorithm over Q (exact, so its basis generates the input's ideal by
// construction, and shares no code with the F4 modulo q the proof runs): a basis equal to
// Buchberger's must be proven or left unproven, never refuted, and one that Buchberger shows
// to generate a larger ideal must be refuted or left unproven, never proven.
#include "algebra/modular/ideal_equality.h"

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>
#include <vector>

#include "algebra/error.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/verify.h"
#include "algebra/modular/modular_groebner.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

using Status = IdealEquality::Status;

std::vector<Polynomial> exact_basis(const std::vector<Polynomial>& generators) {
    return buchberger(generators).basis;
}

// A basis the caller claims to be a Gröbner basis containing the generators: the proof's
// preconditions, checked here by the rational division algorithm.
IdealEquality prove(const std::vector<Polynomial>& basis,
                    const std::vector<Polynomial>& generators) {
    EXPECT_TRUE(check_groebner_basis(basis, generators).ok);
    return prove_ideal_equality(basis, generators);
}

std::vector<Polynomial> polynomials(const IdealFile& file, const std::vector<std::string>& texts) {
    std::vector<Polynomial> out;
    for (const std::string& t : texts) {
        out.push_back(parse_polynomial(t, file.ring));
    }
    return out;
}

// The proof's verdict on `basis` (Buchberger's basis of the file when empty) for the ideal of
// the file `text`: `status`, with an argument that names `phrase`.
void expect_verdict(const std::string& text, const std::vector<std::string>& basis, Status status,
                    const std::string& phrase = "") {
    const IdealFile f = parse_ideal_file(text);
    const IdealEquality e =
        prove(basis.empty() ? exact_basis(f.generators) : polynomials(f, basis), f.generators);
    EXPECT_EQ(e.status, status) << text << e.argument;
    EXPECT_NE(e.argument.find(phrase), std::string::npos) << text << e.argument;
}

std::string bench_file(const std::string& name) {
    return test::read_text(test::source_dir() + "/bench/data/" + name + ".ideal");
}

TEST(IdealEquality, KatsuraHasNoZerosAtInfinityAndIsProven) {
    for (const char* name : {"katsura4", "katsura5", "katsura4_lex"}) {
        expect_verdict(bench_file(name), {}, Status::proven, "top-degree forms");
    }
}

TEST(IdealEquality, ZerosAtInfinityLeaveTheEqualityUnproven) {
    // cyclic-5 has 70 solutions of Bézout's 120; the other 50 are at infinity.
    expect_verdict(bench_file("cyclic5"), {}, Status::not_applicable, "zeros at infinity");
    // A positive-dimensional affine ideal: no case applies.
    expect_verdict("vars: x,y,z\ny-x^2\nz-x^3\n", {}, Status::not_applicable,
                   "infinitely many standard monomials");
}

TEST(IdealEquality, HomogeneousIdealsCompareHilbertSeries) {
    // Positive-dimensional and homogeneous: the twisted cubic's 2×2 minors, and three
    // quadrics in four variables under lex.
    expect_verdict("vars: x,y,z,w\nx*z-y^2\ny*w-z^2\nx*w-y*z\n", {}, Status::proven,
                   "Hilbert series");
    expect_verdict("vars: a,b,c,d\norder: lex\na^2-3*b*c+d^2\n2*a*b-c^2+5*b*d\n7*a*d-b^2+c*d\n", {},
                   Status::proven);
    // A larger homogeneous ideal: its Hilbert series is smaller, which does not refute (q could
    // be unlucky), but must not prove.
    expect_verdict("vars: x,y\nx^2-y^2\n", {"x-y"}, Status::not_proven);
}

TEST(IdealEquality, WrongBasesAreRefuted) {
    // Four solutions and no zeros at infinity: a basis with one solution, or none, is wrong.
    const std::string square = "vars: x,y\nx^2-1\ny^2-1\n";
    expect_verdict(square, {}, Status::proven);
    expect_verdict(square, {"x-1", "y-1"}, Status::refuted, "no zeros at infinity");
    expect_verdict(square, {"1"}, Status::refuted);
    // One generator in two variables cannot make a zero-dimensional ideal.
    expect_verdict("vars: x,y\nx^2+y^2-1\n", {"x", "y-1"}, Status::refuted, "Krull");
    // A variable no generator uses cannot have a power in the ideal.
    expect_verdict("vars: x,y,z\nx^2-1\ny-x\nx*y-1\n", {"x-1", "y-1", "z"}, Status::refuted,
                   "no generator uses z");
    // The zero ideal and a non-zero one.
    const IdealFile circle = parse_ideal_file("vars: x,y\nx^2+y^2-1\n");
    const std::vector<Polynomial> none;
    EXPECT_EQ(prove_ideal_equality(polynomials(circle, {"x"}), none).status, Status::refuted);
    EXPECT_EQ(prove_ideal_equality(none, none).status, Status::proven);
}

TEST(IdealEquality, TheUnitIdealIsProvenByTheHomogenizedInput) {
    // Three lines through no common point, not even at infinity.
    expect_verdict("vars: x,y\nx\ny\nx+y+1\n", {}, Status::proven, "unit ideal");
    // Variables the input does not use are no zeros of it (26 of the 28 here).
    expect_verdict(
        "vars: a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,t,u,v,w,x,y,z,h0,h1\na-1\nb-2\na-b\n", {},
        Status::proven, "unit ideal");
    // Two parallel lines meet at infinity: the unit ideal there is not proven.
    expect_verdict("vars: x,y\nx+y-1\nx+y-2\n", {}, Status::not_proven, "has zeros");
    // Three generators in one variable, with a common zero at infinity only through x^2.
    expect_verdict("vars: x\nx^2-1\nx^2-4\nx^3+x\n", {}, Status::proven);
}

// The proof works in grevlex rings, whose total-degree field holds at most 32 767: an input
// the route computes under lex may not fit them, and the proof then reports it, not throws.
TEST(IdealEquality, ExponentsBeyondTheProofsRingsAreReportedNotThrown) {
    expect_verdict("vars: x,y\norder: lex\nx^20000*y^20000-1\nx-2\n", {}, Status::not_proven,
                   "do not fit");
}

// Every phase honours the deadline: the proof's F4 and Hilbert series throw Timeout.
TEST(IdealEquality, HonoursTheDeadline) {
    const IdealFile f = parse_ideal_file(bench_file("katsura5"));
    const std::vector<Polynomial> basis = exact_basis(f.generators);
    EXPECT_THROW(prove_ideal_equality(basis, f.generators,
                                      std::chrono::steady_clock::now() - std::chrono::seconds(1)),
                 Timeout);
}

// Random square systems of dense quadrics and cubics (generic: no zeros at infinity) in two and
// three variables: the exact basis is proven; the basis of the ideal with one random polynomial
// more, which Buchberger shows to be larger, is refuted.
TEST(IdealEquality, RandomSquareSystemsAgainstBuchberger) {
    std::mt19937 random(20261129);
    std::uniform_int_distribution<int> coefficient(-9, 9);
    int proven = 0, refuted = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const bool three = trial % 2 == 1;
        const std::string vars = three ? "x,y,z" : "x,y";
        const std::vector<std::string> monomials =
            three ? std::vector<std::string>{"x^2", "y^2", "z^2", "x*y", "y*z", "x", "z", "1"}
                  : std::vector<std::string>{"x^3", "x*y^2", "y^3", "x^2", "y", "1"};
        std::string text = "vars: " + vars + "\n";
        const int count = three ? 3 : 2;
        auto random_polynomial = [&] {
            std::string p;
            for (const std::string& m : monomials) {
                p += "+(" + std::to_string(coefficient(random)) + ")*" + m;
            }
            return p;
        };
        for (int k = 0; k < count; ++k) {
            text += random_polynomial() + "\n";
        }
        const IdealFile f = parse_ideal_file(text);
        const std::vector<Polynomial> basis = exact_basis(f.generators);
        const IdealEquality right = prove(basis, f.generators);
        EXPECT_NE(right.status, Status::refuted) << text << right.argument;
        proven += right.status == Status::proven;
        // I + ⟨h⟩ for a random linear h: larger unless h vanishes on every solution.
        std::vector<Polynomial> more = f.generators;
        more.push_back(parse_polynomial(std::to_string(coefficient(random)) + "*x+" +
                                            std::to_string(coefficient(random)) + "*y+1",
                                        f.ring));
        const std::vector<Polynomial> larger = exact_basis(more);
        if (check_groebner_basis(basis, more).ok) {
            continue;  // h is in I: not larger
        }
        const IdealEquality wrong = prove(larger, f.generators);
        EXPECT_NE(wrong.status, Status::proven) << text << wrong.argument;
        refuted += wrong.status == Status::refuted;
    }
    // Generic systems: every case decided (a degenerate draw would show here, not pass).
    EXPECT_EQ(proven, 12);
    EXPECT_GE(refuted, 10);
}

// The modular route runs the proof after the certification, on one thread or several, and a
// refutation sends it on to more primes. Both forced primes divide
// P = 2147483647 · 2147483629, so modulo each the input is x^2 − 1, x^2 − 2: the unit ideal, on
// which they agree, and {1} passes the certification (it is a Gröbner basis containing the
// input). Over Q the ideal has four solutions.
TEST(IdealEquality, TheModularRouteRetriesARefutedLift) {
    const IdealFile f = parse_ideal_file(
        "vars: x,y\norder: grevlex\nx^2+4611685975477714963*y-1\n"
        "x^2+4611685975477714963*y^2-2\n");
    for (int threads : {1, 2}) {
        ModularOptions forced;
        forced.primes = {2147483647u, 2147483629u};
        forced.threads = threads;
        ModularStats stats;
        const GroebnerResult r = modular_groebner(f.generators, forced, &stats);
        EXPECT_EQ(format_polynomials(r.basis, *f.ring, OutputFormat::normalized),
                  format_polynomials(exact_basis(f.generators), *f.ring, OutputFormat::normalized))
            << threads;
        EXPECT_TRUE(stats.certified);
        ASSERT_TRUE(stats.equality.has_value());
        EXPECT_EQ(stats.equality->status, Status::proven) << stats.equality->argument;
        EXPECT_GT(stats.primes_used.size(), 2u);
    }
    // Without the proof the wrong lift was the answer: the certificate alone accepts {1}.
    EXPECT_TRUE(check_groebner_basis(polynomials(f, {"1"}), f.generators).ok);
}

}  // namespace
}  // namespace locus::algebra
