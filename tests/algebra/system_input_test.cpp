// Other systems' formats: what locus prints for Singular and Macaulay2 it reads back to the same
// ring and generators (for every literature case, whatever its order), pasted sessions with
// comments and extra statements, errors at their line and column; the new output formats
// (SymPy, Maple, Mathematica) and the renaming of names a system reserves; ideal files whose
// generators span lines.
#include "algebra/system_input.h"

#include <gtest/gtest.h>

#include <numeric>

#include "algebra/error.h"
#include "algebra/groebner/buchberger.h"
#include "algebra/print.h"
#include "tests/support/ideal_cases.h"

namespace locus::algebra {
namespace {

// `g` (of `from`) as a polynomial of `to`, variables matched by name.
Polynomial by_names(const Polynomial& g, const RingPtr& to) {
    const auto& names = g.ring()->variable_names();
    std::vector<std::size_t> map(names.size());
    for (std::size_t v = 0; v < names.size(); ++v) {
        map[v] = *to->variable_index(names[v]);
    }
    return g.in_ring(to, map);
}

// Every literature case: its reduced basis printed for the system and read back gives the same
// polynomials, and the ring read back has the same order (its reduced basis of the read
// generators is the same basis: the order was understood, not only the text).
TEST(SystemInput, SingularAndMacaulay2OutputReadsBack) {
    for (const std::string& name : test::known_case_names()) {
        const IdealFile ideal = parse_ideal_file(
            test::read_text(test::source_dir() + "/tests/data/known/" + name + ".ideal"));
        const std::vector<Polynomial> basis = buchberger(ideal.generators).basis;
        for (const OutputFormat format : {OutputFormat::singular, OutputFormat::macaulay2}) {
            const std::string text = format_polynomials(basis, *ideal.ring, format);
            ASSERT_EQ(detect_ideal_format(text), format == OutputFormat::singular
                                                     ? IdealFormat::singular
                                                     : IdealFormat::macaulay2)
                << name;
            const IdealFile back = parse_ideal_text(text, detect_ideal_format(text));
            ASSERT_EQ(back.generators.size(), basis.size()) << name << "\n" << text;
            for (std::size_t i = 0; i < basis.size(); ++i) {
                EXPECT_EQ(by_names(back.generators[i], ideal.ring), basis[i]) << name;
            }
            const std::vector<Polynomial> again = buchberger(back.generators).basis;
            ASSERT_EQ(again.size(), basis.size()) << name << "\n" << text;
            for (std::size_t i = 0; i < basis.size(); ++i) {
                EXPECT_EQ(by_names(again[i], ideal.ring), basis[i]) << name << "\n" << text;
            }
        }
    }
}

TEST(SystemInput, PastedSingularSession) {
    const IdealFile f = parse_singular_input(
        "// from a Singular session\n"
        "LIB \"poly.lib\";\n"
        "ring r = 32003, (x,y,z), lp;   /* lex */\n"
        "option(redSB);\n"
        "ideal I = x^2 + y*z,   // the first\n"
        "          (y - 1)^2,\n"
        "          z^3 - 1/2;\n"
        "ideal J = std(I);\n");
    EXPECT_EQ(f.characteristic, 32003u);
    EXPECT_EQ(f.ring->order().kind(), MonomialOrder::Kind::lex);
    ASSERT_EQ(f.generators.size(), 3u);
    EXPECT_EQ(to_string(f.generators[1]), "y^2-2*y+1");
    EXPECT_EQ(f.generator_lines[2], 7u);
    const IdealFile q = parse_singular_input("ring R=QQ,(a,b),(dp(1),dp(1));ideal I=a*b-1,b^2;");
    EXPECT_EQ(q.ring->order().kind(), MonomialOrder::Kind::elimination);
    EXPECT_EQ(q.characteristic, 0u);
}

TEST(SystemInput, PastedMacaulay2Session) {
    const IdealFile f = parse_macaulay2_input(
        "-- a Macaulay2 session\n"
        "R = ZZ/101[x, y, z, MonomialOrder => GLex];\n"
        "I = ideal(x^2 - y*z,\n"
        "          3/4*z^2 + 1)  -* block comment *-\n"
        "gens gb I\n");
    EXPECT_EQ(f.characteristic, 101u);
    EXPECT_EQ(f.ring->order().kind(), MonomialOrder::Kind::grlex);
    ASSERT_EQ(f.generators.size(), 2u);
    EXPECT_EQ(f.generator_lines[1], 4u);
    const IdealFile e = parse_macaulay2_input(
        "S = QQ[t,x,y, MonomialOrder=>Eliminate 1]\n"
        "J = ideal{x - t^2, y - t^3}");
    EXPECT_EQ(e.ring->order().kind(), MonomialOrder::Kind::matrix);
    // Eliminate 1 keeps t out of the elimination ideal's part of the basis.
    const auto basis = buchberger(e.generators).basis;
    const bool has_curve = std::any_of(basis.begin(), basis.end(), [](const Polynomial& g) {
        return !g.contains_variable(0) && to_string(g) == "x^3-y^2";
    });
    EXPECT_TRUE(has_curve);
    EXPECT_TRUE(parse_macaulay2_input("R = QQ[x]\nI = ideal(0_R)").generators.empty());
}

// Errors point at the offending character, in the file's own lines and columns.
TEST(SystemInput, ErrorsNameLineAndColumn) {
    const auto position = [](const std::string& text, bool singular) {
        try {
            if (singular) {
                parse_singular_input(text);
            } else {
                parse_macaulay2_input(text);
            }
        } catch (const ParseError& e) {
            return std::to_string(e.line()) + ":" + std::to_string(e.column());
        }
        return std::string("no error");
    };
    EXPECT_EQ(position("ring r = 0, (x,y), ds;\nideal I = x;", true), "1:20");
    EXPECT_EQ(position("ring r = 4, (x,y), dp;\nideal I = x;", true), "1:10");
    EXPECT_EQ(position("ring r = 0, (x,y), dp;\nideal I = x,\n  y + * 2;", true), "3:7");
    EXPECT_EQ(position("ideal I = x;", true), "1:1");
    EXPECT_EQ(position("ring r = 0, (x,y), dp;", true), "1:23");
    EXPECT_EQ(position("R = QQ[x,y, MonomialOrder => Foo]\nI = ideal(x)", false), "1:30");
    EXPECT_EQ(position("R = QQ[x,y\nI = ideal(x)", false), "1:7");
    EXPECT_EQ(position("R = QQ[x,y]\nI = ideal(x, w)", false), "2:14");
    EXPECT_EQ(position("R = ZZ/100[x]\nI = ideal(x)", false), "1:8");
}

// Review regressions: quotient rings were read as if the quotient's ideal were the input, and
// Macaulay2's Eliminate k for k >= 2 built a singular matrix; a generator continued across a
// blank or comment line reported its errors lines too early.
TEST(SystemInput, ReviewRegressions) {
    EXPECT_THROW(parse_macaulay2_input("R = QQ[x,y]/ideal(x^2-y)\nI = ideal(x^3-1)"), ParseError);
    EXPECT_THROW(parse_singular_input("ring r=0,(x,y),dp;\nqring q = std(ideal(x^2-y));\n"
                                      "ideal I = x^3-1;"),
                 ParseError);
    const IdealFile e = parse_macaulay2_input(
        "R = QQ[t,s,x,y,z, MonomialOrder => Eliminate 2]\nI = ideal(x-t-s, y-t*s, z-t^2)");
    EXPECT_EQ(e.ring->order().kind(), MonomialOrder::Kind::matrix);
    // Every basis element free of t and s lies in the elimination ideal; there is one.
    const auto basis = buchberger(e.generators).basis;
    EXPECT_TRUE(std::any_of(basis.begin(), basis.end(), [](const Polynomial& g) {
        return !g.contains_variable(0) && !g.contains_variable(1);
    }));
    try {
        parse_ideal_file("vars: x,y\n(x +\n\n# note\ny $)\n");
        FAIL();
    } catch (const ParseError& error) {
        EXPECT_EQ(error.line(), 5u);
        EXPECT_EQ(error.column(), 3u);
    }
}

TEST(SystemInput, DetectsEachFormat) {
    EXPECT_EQ(detect_ideal_format("# c\nvars: x\nx\n"), IdealFormat::ideal_file);
    EXPECT_EQ(detect_ideal_format("// c\n ring r=0,(x),dp; ideal I=x;"), IdealFormat::singular);
    EXPECT_EQ(detect_ideal_format("R = QQ [x]\nI = ideal(x)"), IdealFormat::macaulay2);
    EXPECT_EQ(detect_ideal_format("R = ZZ / 7 [x]\nI = ideal(x)"), IdealFormat::macaulay2);
    EXPECT_EQ(detect_ideal_format("x,y\n0\nx-y\n"), IdealFormat::msolve);
    EXPECT_EQ(detect_ideal_format("x^2\n"), IdealFormat::ideal_file);
}

TEST(SystemOutput, SympyMapleMathematica) {
    const RingPtr r = PolyRing::make({"x", "y"}, MonomialOrder::lex(2));
    const std::vector<Polynomial> basis = {parse_polynomial("y^2 - 1/3", r),
                                           parse_polynomial("x - 2*y", r)};
    EXPECT_EQ(format_polynomials(basis, *r, OutputFormat::sympy),
              "from sympy import Rational, symbols\n"
              "x, y = symbols('x y')\n"
              "# a reduced basis under order='lex': groebner(G, x, y, order='lex')\n"
              "G = [\n    y**2-Rational(1, 3),\n    x-2*y\n]\n");
    EXPECT_EQ(format_polynomials(basis, *r, OutputFormat::maple),
              "# a reduced basis under plex(x, y): Groebner[Basis](G, plex(x, y))\n"
              "G := [\n  y^2-1/3,\n  x-2*y];\n");
    EXPECT_EQ(format_polynomials(basis, *r, OutputFormat::mathematica),
              "(* a reduced basis under GroebnerBasis[G, {x, y}, MonomialOrder -> "
              "Lexicographic] *)\nG = {\n  y^2-1/3,\n  x-2*y};\n");
    EXPECT_EQ(format_polynomial(basis[0], OutputFormat::sympy), "y**2-Rational(1, 3)");
    EXPECT_EQ(format_polynomial(basis[0], OutputFormat::latex), "y^{2}-\\frac{1}{3}");
}

TEST(SystemOutput, ReservedNamesAreRenamedOrQuoted) {
    const RingPtr r =
        PolyRing::make({"r", "ring", "a_b", "I", "lambda"}, MonomialOrder::grevlex(5));
    const std::vector<Polynomial> basis = {parse_polynomial("r*ring - a_b + I*lambda", r)};
    const std::string singular = format_polynomials(basis, *r, OutputFormat::singular);
    EXPECT_NE(singular.find("// renamed (reserved or used by this output): r -> r_, ring -> "
                            "ring_\n"),
              std::string::npos)
        << singular;
    EXPECT_NE(singular.find("(r_,ring_,a_b,I,lambda)"), std::string::npos) << singular;
    // Read back, the renamed ring is consistent: same polynomial up to the new names.
    const IdealFile back = parse_singular_input(singular);
    EXPECT_EQ(to_string(back.generators[0]), "r_*ring_+I*lambda-a_b");
    const std::string mathematica = format_polynomials(basis, *r, OutputFormat::mathematica);
    EXPECT_NE(mathematica.find("a_b -> abv, I -> Iv"), std::string::npos) << mathematica;
    EXPECT_EQ(mathematica.find("a_b+"), std::string::npos);
    const std::string maple = format_polynomials(basis, *r, OutputFormat::maple);
    EXPECT_NE(maple.find("`I`*lambda"), std::string::npos) << maple;
    const std::string sympy = format_polynomials(basis, *r, OutputFormat::sympy);
    EXPECT_NE(sympy.find("r, ring, a_b, I, lambda_ = symbols('r ring a_b I lambda')"),
              std::string::npos)
        << sympy;
    EXPECT_EQ(to_latex(parse_polynomial("a_b", r)), "\\mathit{a\\_b}");
}

TEST(IdealFile, GeneratorsSpanLinesAndCommasSeparate) {
    const IdealFile f = parse_ideal_file(
        "vars: x,y\n"
        "(x + y)^2 *\n"
        "   (x - y) +   # continues after an operator\n"
        "  1\n"
        "x^2 + (y\n"
        "   - 1), x*y,\n"
        "y^3\n");
    ASSERT_EQ(f.generators.size(), 4u);
    EXPECT_EQ(f.generator_lines, (std::vector<std::size_t>{2, 5, 6, 7}));
    EXPECT_EQ(to_string(f.generators[1]), "x^2+y-1");
    EXPECT_EQ(to_string(f.generators[2]), "x*y");
    try {
        parse_ideal_file("vars: x,y\nx +\n  y * * 2\n");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 3u);
        EXPECT_EQ(e.column(), 7u);
    }
    EXPECT_THROW(parse_ideal_file("vars: x\nx, , x\n"), ParseError);
    EXPECT_THROW(parse_ideal_file("vars: x\n(x +\n"), ParseError);
}

}  // namespace
}  // namespace locus::algebra
