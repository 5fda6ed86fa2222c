#include "algebra/print.h"

#include <algorithm>

#include "algebra/error.h"

namespace locus::algebra {

OutputFormat parse_output_format(std::string_view name) {
    if (name == "normalized" || name == "locus") {
        return OutputFormat::normalized;
    }
    if (name == "singular") {
        return OutputFormat::singular;
    }
    if (name == "macaulay2" || name == "m2") {
        return OutputFormat::macaulay2;
    }
    if (name == "latex") {
        return OutputFormat::latex;
    }
    if (name == "msolve") {
        return OutputFormat::msolve;
    }
    throw InputError("output format " + std::string(name),
                     "expected normalized, singular, macaulay2, latex or msolve");
}

namespace {

// Shared term walk: `monomial` writes the monomial of term i (empty for 1), `coefficient`
// writes the absolute value of a coefficient, `times` separates coefficient and monomial.
template <class MonomialWriter, class CoefficientWriter>
std::string write_terms(const Polynomial& f, MonomialWriter monomial, CoefficientWriter coefficient,
                        std::string_view times) {
    if (f.is_zero()) {
        return "0";
    }
    std::string s;
    Rational magnitude;
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        const Rational& c = f.coefficient(i);
        if (c.sign() < 0) {
            s += "-";
        } else if (i > 0) {
            s += "+";
        }
        fmpq_abs(magnitude.get(), c.get());
        const std::string mono = monomial(f.exponents(i));
        if (mono.empty()) {
            s += coefficient(magnitude);
        } else if (magnitude.is_one()) {
            s += mono;
        } else {
            s += coefficient(magnitude);
            s += times;
            s += mono;
        }
    }
    return s;
}

std::string plain_monomial(const PolyRing& ring, const std::vector<std::uint32_t>& e) {
    std::string s;
    for (std::size_t v = 0; v < e.size(); ++v) {
        if (e[v] == 0) {
            continue;
        }
        if (!s.empty()) {
            s += "*";
        }
        s += ring.variable_name(v);
        if (e[v] > 1) {
            s += '^';
            s += std::to_string(e[v]);
        }
    }
    return s;
}

std::string join_ints(const std::vector<std::int64_t>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i > 0) {
            s += ',';
        }
        s += std::to_string(v[i]);
    }
    return s;
}

// Variables in a declaration order that puts each block of a block order together, and the
// block sizes (one block for orders that need none).
struct BlockLayout {
    std::vector<std::size_t> variables;
    std::vector<std::size_t> block_sizes;
};

BlockLayout block_layout(const PolyRing& ring) {
    BlockLayout b;
    const auto& order = ring.order();
    if (order.kind() == MonomialOrder::Kind::elimination) {
        b.variables = order.eliminated();
        for (std::size_t i = 0; i < ring.num_vars(); ++i) {
            if (!std::binary_search(order.eliminated().begin(), order.eliminated().end(), i)) {
                b.variables.push_back(i);
            }
        }
        b.block_sizes = {order.eliminated().size(), ring.num_vars() - order.eliminated().size()};
        if (b.block_sizes[1] == 0) {
            b.block_sizes.pop_back();
        }
    } else {
        for (std::size_t i = 0; i < ring.num_vars(); ++i) {
            b.variables.push_back(i);
        }
        b.block_sizes = {ring.num_vars()};
    }
    return b;
}

std::string variable_list(const PolyRing& ring, const BlockLayout& b) {
    std::string s;
    for (std::size_t i = 0; i < b.variables.size(); ++i) {
        s += (i ? "," : "") + ring.variable_name(b.variables[i]);
    }
    return s;
}

std::string macaulay2_ring(const PolyRing& ring, std::uint32_t characteristic) {
    const BlockLayout b = block_layout(ring);
    const auto& order = ring.order();
    std::string mo;
    switch (order.kind()) {
    case MonomialOrder::Kind::lex:
        mo = "Lex";
        break;
    case MonomialOrder::Kind::grlex:
        mo = "GLex";
        break;
    case MonomialOrder::Kind::grevlex:
        mo = "GRevLex";
        break;
    case MonomialOrder::Kind::weighted:
        // GRevLex => w is weighted degree, then reverse lex: Singular's wp and locus's weights.
        mo = "{GRevLex => {" + join_ints(order.matrix_rows()[0]) + "}}";
        break;
    case MonomialOrder::Kind::elimination:
        mo = "{GRevLex => " + std::to_string(b.block_sizes[0]);
        if (b.block_sizes.size() > 1) {
            mo += ", GRevLex => " + std::to_string(b.block_sizes[1]);
        }
        mo += "}";
        break;
    case MonomialOrder::Kind::matrix: {
        mo = "{";
        const auto& rows = order.matrix_rows();
        for (std::size_t r = 0; r < rows.size(); ++r) {
            mo += (r ? ", " : "") + std::string("Weights => {") + join_ints(rows[r]) + "}";
        }
        mo += "}";
        break;
    }
    }
    const std::string field = characteristic == 0 ? "QQ" : "ZZ/" + std::to_string(characteristic);
    return "R = " + field + "[" + variable_list(ring, b) + ", MonomialOrder => " + mo + "];";
}

}  // namespace

std::string to_string(const Polynomial& f) {
    const PolyRing& ring = *f.ring();
    return write_terms(
        f, [&](const std::vector<std::uint32_t>& e) { return plain_monomial(ring, e); },
        [](const Rational& c) { return c.to_string(); }, "*");
}

std::string to_latex(const Polynomial& f) {
    const PolyRing& ring = *f.ring();
    auto monomial = [&](const std::vector<std::uint32_t>& e) {
        std::string s;
        for (std::size_t v = 0; v < e.size(); ++v) {
            if (e[v] == 0) {
                continue;
            }
            if (!s.empty()) {
                s += " ";
            }
            const std::string& name = ring.variable_name(v);
            // Names with digits become subscripts: x12 -> x_{12}.
            const auto digit = name.find_first_of("0123456789");
            if (digit != std::string::npos && digit > 0 &&
                name.find_first_not_of("0123456789", digit) == std::string::npos) {
                std::string stem = name.substr(0, digit);
                if (stem.size() > 1 && stem.back() == '_') {
                    stem.pop_back();  // y_2 -> y_{2}, not y__{2}
                }
                s += stem + "_{" + name.substr(digit) + "}";
            } else if (name.size() > 1) {
                s += "\\mathit{" + name + "}";
            } else {
                s += name;
            }
            if (e[v] > 1) {
                s += "^{" + std::to_string(e[v]) + "}";
            }
        }
        return s;
    };
    auto coefficient = [](const Rational& c) {
        const std::string s = c.to_string();
        const auto slash = s.find('/');
        if (slash == std::string::npos) {
            return s;
        }
        return "\\frac{" + s.substr(0, slash) + "}{" + s.substr(slash + 1) + "}";
    };
    return write_terms(f, monomial, coefficient, " ");
}

std::vector<Polynomial> normalize_basis(std::vector<Polynomial> basis) {
    std::vector<Polynomial> out;
    for (auto& g : basis) {
        if (!g.is_zero()) {
            out.push_back(g.monic());
        }
    }
    std::sort(out.begin(), out.end(), [](const Polynomial& a, const Polynomial& b) {
        return a.ring()->layout().compare(a.leading_monomial(), b.leading_monomial()) < 0;
    });
    return out;
}

std::string singular_ring(const PolyRing& ring, std::string_view ring_name,
                          std::uint32_t characteristic) {
    const BlockLayout b = block_layout(ring);
    const auto& order = ring.order();
    std::string o;
    switch (order.kind()) {
    case MonomialOrder::Kind::lex:
        o = "lp";
        break;
    case MonomialOrder::Kind::grlex:
        o = "Dp";
        break;
    case MonomialOrder::Kind::grevlex:
        o = "dp";
        break;
    case MonomialOrder::Kind::weighted:
        o = "wp(" + join_ints(order.matrix_rows()[0]) + ")";
        break;
    case MonomialOrder::Kind::elimination:
        o = "(dp(" + std::to_string(b.block_sizes[0]) + ")";
        if (b.block_sizes.size() > 1) {
            o += ",dp(" + std::to_string(b.block_sizes[1]) + ")";
        }
        o += ")";
        break;
    case MonomialOrder::Kind::matrix: {
        // Singular takes the matrix row by row, negative entries included (checked against
        // Singular 4.3.1 by scripts/capture-singular-oracle).
        std::vector<std::int64_t> entries;
        for (const auto& row : order.matrix_rows()) {
            entries.insert(entries.end(), row.begin(), row.end());
        }
        o = "M(" + join_ints(entries) + ")";
        break;
    }
    }
    return "ring " + std::string(ring_name) + " = " + std::to_string(characteristic) + ", (" +
           variable_list(ring, b) + "), " + o + ";";
}

std::string format_polynomials(std::span<const Polynomial> polys, const PolyRing& ring,
                               OutputFormat format, std::string_view ideal_name,
                               std::uint32_t characteristic) {
    std::string out;
    switch (format) {
    case OutputFormat::normalized:
    case OutputFormat::latex:
        for (const auto& p : polys) {
            out += (format == OutputFormat::latex ? to_latex(p) : to_string(p)) + "\n";
        }
        return out;
    case OutputFormat::singular:
        out =
            singular_ring(ring, "r", characteristic) + "\nideal " + std::string(ideal_name) + " =";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n  " : "\n  ") + to_string(polys[i]);
        }
        if (polys.empty()) {
            out += " 0";
        }
        return out + ";\n";
    case OutputFormat::macaulay2:
        out = macaulay2_ring(ring, characteristic) + "\n" + std::string(ideal_name) + " = ideal(";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n  " : "\n  ") + to_string(polys[i]);
        }
        if (polys.empty()) {
            out += "0_R";
        }
        return out + ")\n";
    case OutputFormat::msolve:
        for (std::size_t i = 0; i < ring.num_vars(); ++i) {
            out += (i ? "," : "") + ring.variable_name(i);
        }
        out += "\n" + std::to_string(characteristic) + "\n";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += to_string(polys[i]) + (i + 1 < polys.size() ? ",\n" : "\n");
        }
        if (polys.empty()) {
            out += "0\n";
        }
        return out;
    }
    return out;
}

std::string to_ideal_file(std::span<const Polynomial> generators, const PolyRing& ring,
                          std::uint32_t characteristic) {
    std::string out = "vars: ";
    for (std::size_t i = 0; i < ring.num_vars(); ++i) {
        out += (i ? "," : "") + ring.variable_name(i);
    }
    out += "\norder: " + ring.order().to_string(ring.variable_names()) + "\n";
    if (characteristic != 0) {
        out += "characteristic: " + std::to_string(characteristic) + "\n";
    }
    for (const auto& g : generators) {
        out += to_string(g) + "\n";
    }
    return out;
}

}  // namespace locus::algebra
