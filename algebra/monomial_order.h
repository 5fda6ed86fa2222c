// A monomial order on n variables, as a value (no global "current order").
//
// Every order has one general representation, an n×n integer matrix M of full rank whose first
// non-zero entry in each column is positive: a > b iff M·a > M·b lexicographically (Cox–Little–
// O'Shea, IVA ch. 2 §4 ex. 6–12; Robbiano's matrix orders). Named orders are recognised so that
// packed monomials can be compared with a few word comparisons (see monomial.h): the order also
// describes its *comparison fields*, the sequence of values (weighted degrees, exponents, negated
// exponents) whose lexicographic comparison decides it.
//
// Variables are indexed in declared order; declared order is the tie-break (x > y > z).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace locus::algebra {

// One comparison field: either a linear form with non-negative integer weights over the
// exponents, or the exponent of one variable, possibly negated (larger exponent = smaller).
struct OrderField {
    std::vector<std::int64_t> weights;  // empty for a variable field
    std::size_t variable = 0;           // for a variable field
    bool negated = false;               // for a variable field
    bool is_variable() const { return weights.empty(); }
};

class MonomialOrder {
  public:
    enum class Kind { lex, grlex, grevlex, weighted, elimination, matrix };

    static MonomialOrder lex(std::size_t num_vars);
    static MonomialOrder grlex(std::size_t num_vars);
    static MonomialOrder grevlex(std::size_t num_vars);
    // Weighted degree with positive integer weights, ties broken by grevlex's reverse-lex rule
    // (Singular's wp).
    static MonomialOrder weighted(std::vector<std::int64_t> weights);
    // Block order eliminating `eliminated` (variable indices): first block those variables in
    // declared order with grevlex, second block the rest in declared order with grevlex.
    static MonomialOrder elimination(std::size_t num_vars, std::vector<std::size_t> eliminated);
    // General matrix order; throws InputError unless square, of full rank and global (the first
    // non-zero entry of each column positive, so that 1 is the smallest monomial).
    static MonomialOrder matrix(std::vector<std::vector<std::int64_t>> rows);

    Kind kind() const { return kind_; }
    // Every entry of the first weight row positive (grlex, grevlex, positive weights): a
    // degree order, under which sugar strategies and batched F4 steps pay off.
    bool is_degree_order() const;
    std::size_t num_vars() const { return num_vars_; }
    const std::vector<std::vector<std::int64_t>>& matrix_rows() const { return matrix_; }
    const std::vector<OrderField>& fields() const { return fields_; }
    const std::vector<std::size_t>& eliminated() const { return eliminated_; }

    // Reference comparison on plain exponent vectors through the matrix: -1, 0 or 1.
    int compare(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) const;

    // The order as written in ideal files: lex, grlex, grevlex, weights(1,2,3), elim(t,u),
    // matrix((1,1),(0,1)).
    std::string to_string(const std::vector<std::string>& variable_names) const;

    friend bool operator==(const MonomialOrder& a, const MonomialOrder& b) {
        return a.kind_ == b.kind_ && a.matrix_ == b.matrix_;
    }

  private:
    MonomialOrder(Kind kind, std::size_t num_vars) : kind_(kind), num_vars_(num_vars) {}

    Kind kind_;
    std::size_t num_vars_;
    std::vector<std::vector<std::int64_t>> matrix_;
    std::vector<OrderField> fields_;
    std::vector<std::size_t> eliminated_;
};

// Reads an order as written in ideal files (see to_string); names in elim(...) refer to
// `variable_names`. Throws ParseError with `column` offset by `first_column` - 1.
MonomialOrder parse_monomial_order(std::string_view text,
                                   const std::vector<std::string>& variable_names,
                                   std::size_t line = 1, std::size_t first_column = 1);

}  // namespace locus::algebra
