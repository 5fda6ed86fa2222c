#include "algebra/monomial_order.h"

#include <flint/fmpz_mat.h>

#include <algorithm>
#include <cctype>
#include <numeric>

#include "algebra/error.h"

namespace locus::algebra {
namespace {

std::vector<std::int64_t> unit_row(std::size_t n, std::size_t i, std::int64_t value = 1) {
    std::vector<std::int64_t> row(n, 0);
    row[i] = value;
    return row;
}

OrderField variable_field(std::size_t var, bool negated) {
    OrderField f;
    f.variable = var;
    f.negated = negated;
    return f;
}

OrderField linear_field(std::vector<std::int64_t> weights) {
    OrderField f;
    f.weights = std::move(weights);
    return f;
}

// Exact rank over Q (FLINT), so large weights cannot overflow.
std::size_t matrix_rank(const std::vector<std::vector<std::int64_t>>& rows) {
    const auto n = static_cast<slong>(rows.size());
    const auto cols = static_cast<slong>(rows.empty() ? 0 : rows[0].size());
    fmpz_mat_t m;
    fmpz_mat_init(m, n, cols);
    for (slong r = 0; r < n; ++r) {
        for (slong c = 0; c < cols; ++c) {
            fmpz_set_si(fmpz_mat_entry(m, r, c),
                        rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]);
        }
    }
    const slong rank = fmpz_mat_rank(m);
    fmpz_mat_clear(m);
    return static_cast<std::size_t>(rank);
}

}  // namespace

MonomialOrder MonomialOrder::lex(std::size_t n) {
    MonomialOrder o(Kind::lex, n);
    for (std::size_t i = 0; i < n; ++i) {
        o.matrix_.push_back(unit_row(n, i));
        o.fields_.push_back(variable_field(i, false));
    }
    return o;
}

MonomialOrder MonomialOrder::grlex(std::size_t n) {
    MonomialOrder o(Kind::grlex, n);
    o.matrix_.push_back(std::vector<std::int64_t>(n, 1));
    o.fields_.push_back(linear_field(std::vector<std::int64_t>(n, 1)));
    for (std::size_t i = 0; i < n; ++i) {
        if (i + 1 < n) {
            o.matrix_.push_back(unit_row(n, i));
        }
        o.fields_.push_back(variable_field(i, false));
    }
    return o;
}

MonomialOrder MonomialOrder::grevlex(std::size_t n) {
    std::vector<std::int64_t> ones(n, 1);
    MonomialOrder o = weighted(ones);
    o.kind_ = Kind::grevlex;
    return o;
}

MonomialOrder MonomialOrder::weighted(std::vector<std::int64_t> weights) {
    const std::size_t n = weights.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (weights[i] <= 0) {
            throw InputError("weights(...)",
                             "weight " + std::to_string(i + 1) + " must be a positive integer");
        }
    }
    MonomialOrder o(Kind::weighted, n);
    o.matrix_.push_back(weights);
    o.fields_.push_back(linear_field(weights));
    // Reverse-lex tie-break: among equal weighted degrees the smaller last exponent wins.
    for (std::size_t i = n; i-- > 0;) {
        if (i > 0) {
            o.matrix_.push_back(unit_row(n, i, -1));
        }
        o.fields_.push_back(variable_field(i, true));
    }
    return o;
}

MonomialOrder MonomialOrder::elimination(std::size_t n, std::vector<std::size_t> eliminated) {
    std::sort(eliminated.begin(), eliminated.end());
    eliminated.erase(std::unique(eliminated.begin(), eliminated.end()), eliminated.end());
    if (eliminated.empty() || eliminated.back() >= n) {
        throw InputError("elim(...)", "needs at least one variable of the ring");
    }
    MonomialOrder o(Kind::elimination, n);
    std::vector<std::size_t> rest;
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::binary_search(eliminated.begin(), eliminated.end(), i)) {
            rest.push_back(i);
        }
    }
    for (const auto* block : {&eliminated, &rest}) {
        if (block->empty()) {
            continue;
        }
        std::vector<std::int64_t> degree(n, 0);
        for (std::size_t v : *block) {
            degree[v] = 1;
        }
        o.matrix_.push_back(degree);
        o.fields_.push_back(linear_field(degree));
        for (std::size_t k = block->size(); k-- > 0;) {
            if (k > 0) {
                o.matrix_.push_back(unit_row(n, (*block)[k], -1));
            }
            o.fields_.push_back(variable_field((*block)[k], true));
        }
    }
    o.eliminated_ = std::move(eliminated);
    return o;
}

MonomialOrder MonomialOrder::matrix(std::vector<std::vector<std::int64_t>> rows) {
    const std::size_t n = rows.size();
    for (const auto& row : rows) {
        if (row.size() != n) {
            throw InputError("matrix(...)", "the matrix must be square");
        }
    }
    for (std::size_t c = 0; c < n; ++c) {
        for (std::size_t r = 0; r < n; ++r) {
            if (rows[r][c] < 0) {
                throw InputError("matrix(...)", "column " + std::to_string(c + 1) +
                                                    " has a negative first non-zero entry, so "
                                                    "1 would not be the smallest monomial");
            }
            if (rows[r][c] > 0) {
                break;
            }
        }
    }
    if (matrix_rank(rows) != n) {
        throw InputError("matrix(...)", "the matrix must have full rank");
    }
    MonomialOrder o(Kind::matrix, n);
    o.matrix_ = rows;
    // Packed comparison needs non-negative weights: add multiples of earlier (already
    // non-negative) rows that have a positive entry in the offending column. Earlier rows
    // compare equal whenever this row is consulted, so the order is unchanged.
    std::vector<std::vector<std::int64_t>> nonneg = rows;
    for (std::size_t r = 0; r < n; ++r) {
        for (std::size_t c = 0; c < n; ++c) {
            if (nonneg[r][c] >= 0) {
                continue;
            }
            std::size_t k = 0;
            while (nonneg[k][c] <= 0) {
                ++k;
            }
            const std::int64_t times = (-nonneg[r][c] + nonneg[k][c] - 1) / nonneg[k][c];
            for (std::size_t j = 0; j < n; ++j) {
                nonneg[r][j] += times * nonneg[k][j];
            }
        }
        o.fields_.push_back(linear_field(nonneg[r]));
    }
    for (std::size_t i = 0; i < n; ++i) {
        o.fields_.push_back(variable_field(i, false));
    }
    return o;
}

bool MonomialOrder::is_degree_order() const {
    const auto& first_row = matrix_.front();
    return std::all_of(first_row.begin(), first_row.end(), [](std::int64_t v) { return v > 0; });
}

int MonomialOrder::compare(std::span<const std::uint32_t> a,
                           std::span<const std::uint32_t> b) const {
    for (const auto& row : matrix_) {
        std::int64_t d = 0;
        for (std::size_t i = 0; i < num_vars_; ++i) {
            d += row[i] * (static_cast<std::int64_t>(a[i]) - static_cast<std::int64_t>(b[i]));
        }
        if (d != 0) {
            return d > 0 ? 1 : -1;
        }
    }
    return 0;
}

std::string MonomialOrder::to_string(const std::vector<std::string>& names) const {
    auto join = [](const std::vector<std::int64_t>& v) {
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (i > 0) {
                s += ',';
            }
            s += std::to_string(v[i]);
        }
        return s;
    };
    switch (kind_) {
    case Kind::lex:
        return "lex";
    case Kind::grlex:
        return "grlex";
    case Kind::grevlex:
        return "grevlex";
    case Kind::weighted:
        return "weights(" + join(matrix_[0]) + ")";
    case Kind::elimination: {
        std::string s = "elim(";
        for (std::size_t i = 0; i < eliminated_.size(); ++i) {
            s += (i ? "," : "") + names.at(eliminated_[i]);
        }
        return s + ")";
    }
    case Kind::matrix: {
        std::string s = "matrix(";
        for (std::size_t r = 0; r < matrix_.size(); ++r) {
            s += (r ? ",(" : "(") + join(matrix_[r]) + ")";
        }
        return s + ")";
    }
    }
    return "";
}

namespace {

// A tiny cursor over an order specification, reporting columns for errors.
class OrderReader {
  public:
    OrderReader(std::string_view text, std::size_t line, std::size_t first_column)
        : text_(text), line_(line), first_column_(first_column) {}

    void skip_space() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            ++pos_;
        }
    }
    bool at_end() {
        skip_space();
        return pos_ >= text_.size();
    }
    bool accept(char c) {
        skip_space();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!accept(c)) {
            fail(std::string("'") + c + "'");
        }
    }
    std::string identifier() {
        skip_space();
        const std::size_t start = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
            ++pos_;
        }
        if (start == pos_) {
            fail("a name");
        }
        return std::string(text_.substr(start, pos_ - start));
    }
    std::int64_t integer() {
        skip_space();
        const std::size_t start = pos_;
        if (pos_ < text_.size() && text_[pos_] == '-') {
            ++pos_;
        }
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
            ++pos_;
        }
        if (pos_ == start || (pos_ == start + 1 && text_[start] == '-') || pos_ - start > 12) {
            pos_ = start;
            fail("an integer of at most 12 digits");
        }
        return std::stoll(std::string(text_.substr(start, pos_ - start)));
    }
    std::vector<std::int64_t> integer_list() {
        expect('(');
        std::vector<std::int64_t> values{integer()};
        while (accept(',')) {
            values.push_back(integer());
        }
        expect(')');
        return values;
    }
    [[noreturn]] void fail(const std::string& expected, std::size_t at = SIZE_MAX) {
        if (at == SIZE_MAX) {
            skip_space();
            at = pos_;
        }
        std::string found =
            at < text_.size() ? "'" + std::string(1, text_[at]) + "'" : std::string("end of line");
        throw ParseError(line_, first_column_ + at, expected, found);
    }
    std::size_t position() const { return pos_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t line_, first_column_;
};

}  // namespace

MonomialOrder parse_monomial_order(std::string_view text, const std::vector<std::string>& names,
                                   std::size_t line, std::size_t first_column) {
    OrderReader in(text, line, first_column);
    in.skip_space();
    const std::size_t name_at = in.position();
    const std::string name = in.identifier();
    const std::size_t n = names.size();
    MonomialOrder order = MonomialOrder::lex(n);
    try {
        if (name == "lex") {
            order = MonomialOrder::lex(n);
        } else if (name == "grlex" || name == "deglex") {
            order = MonomialOrder::grlex(n);
        } else if (name == "grevlex" || name == "degrevlex") {
            order = MonomialOrder::grevlex(n);
        } else if (name == "weights") {
            const std::size_t at = in.position();
            auto w = in.integer_list();
            if (w.size() != n) {
                in.fail(std::to_string(n) + " weights, one per variable", at);
            }
            order = MonomialOrder::weighted(std::move(w));
        } else if (name == "elim") {
            in.expect('(');
            std::vector<std::size_t> vars;
            do {
                in.skip_space();
                const std::size_t at = in.position();
                const std::string v = in.identifier();
                auto it = std::find(names.begin(), names.end(), v);
                if (it == names.end()) {
                    in.fail("a declared variable", at);
                }
                vars.push_back(static_cast<std::size_t>(it - names.begin()));
            } while (in.accept(','));
            in.expect(')');
            order = MonomialOrder::elimination(n, std::move(vars));
        } else if (name == "matrix") {
            in.expect('(');
            std::vector<std::vector<std::int64_t>> rows{in.integer_list()};
            while (in.accept(',')) {
                rows.push_back(in.integer_list());
            }
            in.expect(')');
            order = MonomialOrder::matrix(std::move(rows));
        } else {
            in.fail("an order (lex, grlex, grevlex, weights(...), elim(...), matrix(...))",
                    name_at);
        }
    } catch (const InputError& e) {
        throw ParseError(line, first_column + name_at, "a valid order",
                         "'" + std::string(text) + "' (" + e.what() + ")");
    }
    if (!in.at_end()) {
        in.fail("end of the order");
    }
    return order;
}

}  // namespace locus::algebra
