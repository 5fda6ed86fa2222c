// `locus demo`: the main job on a built-in default. Until the renderer lands this computes the
// reduced lex basis of Cox–Little–O'Shea's Lagrange-multiplier system (IVA ch. 2 §8, Example 2:
// extremes of x³+2xyz−z² on the unit sphere), checks it, and prints its statistics.
#include <cstdio>
#include <iostream>

#include "algebra/groebner/buchberger.h"
#include "algebra/groebner/verify.h"
#include "algebra/parse.h"
#include "algebra/print.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

namespace locus::cli {
namespace {

constexpr const char* demo_ideal =
    R"(# CLO, IVA ch. 2 §8: Lagrange multipliers for x^3+2xyz-z^2 on x^2+y^2+z^2=1
vars: lam,x,y,z
order: lex
3*x^2+2*y*z-2*x*lam
2*x*z-2*y*lam
2*x*y-2*z-2*z*lam
x^2+y^2+z^2-1
)";

int run_demo() {
    const algebra::IdealFile ideal = algebra::parse_ideal_file(demo_ideal);
    std::cout << "Input (" << ideal.ring->order().to_string(ideal.ring->variable_names()) << "):\n"
              << algebra::format_polynomials(ideal.generators, *ideal.ring,
                                             algebra::OutputFormat::normalized);
    const algebra::GroebnerResult r = algebra::groebner(ideal.generators);
    std::cout << "\nReduced Gröbner basis:\n"
              << algebra::format_polynomials(r.basis, *ideal.ring,
                                             algebra::OutputFormat::normalized);
    const auto& s = r.stats;
    std::printf(
        "\n%zu pairs created, %zu removed by the product criterion, %zu by the chain "
        "criterion;\n%zu S-polynomials reduced, %zu to zero; %.3f ms\n",
        s.pairs_created, s.removed_by_product, s.removed_by_chain, s.reductions, s.zero_reductions,
        s.seconds * 1e3);
    const algebra::BasisCheck check = algebra::check_groebner_basis(r.basis, ideal.generators);
    std::printf("check: %s (%zu generators and %zu S-pairs reduce to zero)\n",
                check.ok && algebra::is_reduced(r.basis) ? "ok" : "FAILED",
                check.generators_checked, check.pairs_checked);
    return check.ok && algebra::is_reduced(r.basis) ? exit_ok : exit_check_failed;
}

}  // namespace

void add_demo_command(CLI::App& app, int& exit_code) {
    CLI::App* cmd = app.add_subcommand("demo", "Run the built-in demonstration");
    cmd->callback([&exit_code] { exit_code = run_demo(); });
}

}  // namespace locus::cli
