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
    if (name == "sympy") {
        return OutputFormat::sympy;
    }
    if (name == "maple") {
        return OutputFormat::maple;
    }
    if (name == "mathematica") {
        return OutputFormat::mathematica;
    }
    throw InputError("output format " + std::string(name),
                     "expected normalized, singular, macaulay2, latex, msolve, sympy, maple or "
                     "mathematica");
}

std::string singular_ring_named(const PolyRing& ring, std::string_view ring_name,
                                std::uint32_t characteristic,
                                const std::vector<std::string>& names);

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

std::string plain_monomial(const std::vector<std::string>& names,
                           const std::vector<std::uint32_t>& e, std::string_view power = "^") {
    std::string s;
    for (std::size_t v = 0; v < e.size(); ++v) {
        if (e[v] == 0) {
            continue;
        }
        if (!s.empty()) {
            s += "*";
        }
        s += names[v];
        if (e[v] > 1) {
            s += power;
            s += std::to_string(e[v]);
        }
    }
    return s;
}

// f with the variables called `names` (another system's spelling of them).
std::string plain_polynomial(const Polynomial& f, const std::vector<std::string>& names) {
    return write_terms(
        f, [&](const std::vector<std::uint32_t>& e) { return plain_monomial(names, e); },
        [](const Rational& c) { return c.to_string(); }, "*");
}

// Python syntax for SymPy: `**` for powers, Rational(p, q) for fractions (1/3 would be a float).
std::string sympy_polynomial(const Polynomial& f, const std::vector<std::string>& names) {
    return write_terms(
        f, [&](const std::vector<std::uint32_t>& e) { return plain_monomial(names, e, "**"); },
        [](const Rational& c) {
            const std::string text = c.to_string();
            const auto slash = text.find('/');
            return slash == std::string::npos
                       ? text
                       : "Rational(" + text.substr(0, slash) + ", " + text.substr(slash + 1) + ")";
        },
        "*");
}

// Names each system reserves, or that locus's own output uses there (the ring `r`/`R` and the
// ideal's name are added by the caller).
bool is_reserved(OutputFormat format, std::string_view name) {
    static const std::vector<std::string_view> singular = {
        "ring",   "ideal",     "poly",    "int",      "number",    "matrix",    "map",
        "list",   "string",    "vector",  "module",   "def",       "proc",      "return",
        "if",     "else",      "while",   "for",      "break",     "continue",  "quit",
        "exit",   "std",       "print",   "dp",       "lp",        "Dp",        "ds",
        "ls",     "Ds",        "wp",      "Wp",       "ws",        "Ws",        "ordstr",
        "var",    "par",       "char",    "deg",      "size",      "nvars",     "basering",
        "option", "qring",     "intvec",  "intmat",   "bigint",    "link",      "resolution",
        "lead",   "kill",      "type",    "execute",  "system",    "timer",     "rtimer",
        "eval",   "subst",     "diff",    "jacob",    "reduce",    "NF",        "lift",
        "syz",    "eliminate", "sat",     "quotient", "intersect", "dim",       "vdim",
        "mult",   "hilb",      "kbase",   "slimgb",   "groebner",  "factorize", "gcd",
        "LIB",    "keepring",  "setring", "export",   "listvar",   "defined",   "typeof",
        "attrib", "sort",      "minbase", "interred", "QQ",        "ZZ"};
    static const std::vector<std::string_view> macaulay2 = {
        "and",    "or",       "not",         "if",
        "then",   "else",     "do",          "while",
        "for",    "from",     "to",          "in",
        "list",   "new",      "of",          "return",
        "break",  "ideal",    "ring",        "QQ",
        "ZZ",     "RR",       "CC",          "gb",
        "ii",     "pi",       "try",         "when",
        "symbol", "global",   "local",       "threadVariable",
        "time",   "timing",   "elapsedTime", "shield",
        "catch",  "throw",    "except",      "by",
        "step",   "continue", "is",          "xor",
        "true",   "false"};
    static const std::vector<std::string_view> python = {
        "False",   "None",     "True",     "and",      "as",     "assert", "async",  "await",
        "break",   "class",    "continue", "def",      "del",    "elif",   "else",   "except",
        "finally", "for",      "from",     "global",   "if",     "import", "in",     "is",
        "lambda",  "nonlocal", "not",      "or",       "pass",   "raise",  "return", "try",
        "while",   "with",     "yield",    "Rational", "symbols"};
    static const std::vector<std::string_view> maple = {
        "D",      "I",        "Pi",          "gamma",     "Catalan", "true",   "false",
        "FAIL",   "infinity", "and",         "or",        "not",     "xor",    "implies",
        "in",     "do",       "od",          "if",        "fi",      "end",    "proc",
        "local",  "global",   "to",          "by",        "from",    "while",  "for",
        "mod",    "union",    "minus",       "intersect", "subset",  "option", "options",
        "then",   "else",     "elif",        "break",     "next",    "return", "try",
        "catch",  "finally",  "error",       "quit",      "done",    "stop",   "use",
        "module", "export",   "description", "assuming",  "uses",    "Digits", "O"};
    static const std::vector<std::string_view> mathematica = {"C", "D", "E", "I", "K", "N", "O"};
    const std::vector<std::string_view>* list = nullptr;
    switch (format) {
    case OutputFormat::singular:
        list = &singular;
        break;
    case OutputFormat::macaulay2:
        list = &macaulay2;
        break;
    case OutputFormat::sympy:
        list = &python;
        break;
    case OutputFormat::maple:
        list = &maple;
        break;
    case OutputFormat::mathematica:
        // Mathematica's names are letters and digits: `_` makes a pattern (x_ is "any x").
        if (name.find('_') != std::string_view::npos) {
            return true;
        }
        list = &mathematica;
        break;
    case OutputFormat::normalized:
    case OutputFormat::latex:
    case OutputFormat::msolve:
        return false;
    }
    return std::find(list->begin(), list->end(), name) != list->end();
}

// The variables' names in `format`, each reserved one (or one in `taken`) replaced by a fresh
// name; `note` lists the replacements in the system's comment syntax, or is empty. Maple
// quotes instead (`D` stays D, in backquotes). SymPy keeps the symbol's name and renames only
// the Python variable that holds it (see format_polynomials).
struct SystemNames {
    std::vector<std::string> names;
    std::string note;
};

SystemNames system_names(const PolyRing& ring, OutputFormat format,
                         std::initializer_list<std::string_view> taken) {
    SystemNames out{ring.variable_names(), {}};
    const auto in_use = [&](const std::string& candidate) {
        return std::find(out.names.begin(), out.names.end(), candidate) != out.names.end() ||
               std::find(taken.begin(), taken.end(), candidate) != taken.end() ||
               is_reserved(format, candidate);
    };
    std::string renamed;
    for (std::string& name : out.names) {
        const bool clash =
            is_reserved(format, name) || std::find(taken.begin(), taken.end(), name) != taken.end();
        if (!clash) {
            continue;
        }
        const std::string old = name;
        if (format == OutputFormat::maple) {
            name = "`" + name + "`";
            continue;
        }
        std::string stem = old;
        if (format == OutputFormat::mathematica) {
            stem.erase(std::remove(stem.begin(), stem.end(), '_'), stem.end());
            if (stem.empty()) {
                stem = "v";
            }
        }
        std::string candidate = stem + (format == OutputFormat::mathematica ? "v" : "_");
        for (int k = 1; in_use(candidate); ++k) {
            candidate =
                stem + (format == OutputFormat::mathematica ? "v" : "_") + std::to_string(k);
        }
        name = candidate;
        renamed += (renamed.empty() ? "" : ", ") + old + " -> " + name;
    }
    if (!renamed.empty()) {
        const char* open = format == OutputFormat::singular      ? "// "
                           : format == OutputFormat::macaulay2   ? "-- "
                           : format == OutputFormat::mathematica ? "(* "
                                                                 : "# ";
        out.note = std::string(open) + "renamed (reserved or used by this output): " + renamed +
                   (format == OutputFormat::mathematica ? " *)" : "") + "\n";
    }
    return out;
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

std::string variable_list(const std::vector<std::string>& names, const BlockLayout& b) {
    std::string s;
    for (std::size_t i = 0; i < b.variables.size(); ++i) {
        s += (i ? "," : "") + names[b.variables[i]];
    }
    return s;
}

std::string macaulay2_ring(const PolyRing& ring, std::uint32_t characteristic,
                           const std::vector<std::string>& names) {
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
    return "R = " + field + "[" + variable_list(names, b) + ", MonomialOrder => " + mo + "];";
}

}  // namespace

std::string to_string(const Polynomial& f) {
    return plain_polynomial(f, f.ring()->variable_names());
}

std::string to_string(const Polynomial& f, const std::vector<std::string>& names) {
    return plain_polynomial(f, names);
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
                std::string escaped;
                for (const char c : name) {
                    escaped += c == '_' ? std::string("\\_") : std::string(1, c);
                }
                s += "\\mathit{" + escaped + "}";
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
    return singular_ring_named(ring, ring_name, characteristic, ring.variable_names());
}

std::string singular_ring_named(const PolyRing& ring, std::string_view ring_name,
                                std::uint32_t characteristic,
                                const std::vector<std::string>& names) {
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
           variable_list(names, b) + "), " + o + ";";
}

namespace {

// The order as the comment beside a system's list: SymPy's, Maple's and Mathematica's names for
// lex, grlex and grevlex; the others have no common spelling there.
std::string order_comment(const PolyRing& ring, OutputFormat format,
                          const std::vector<std::string>& names) {
    const MonomialOrder::Kind kind = ring.order().kind();
    std::string vars;
    for (std::size_t i = 0; i < names.size(); ++i) {
        vars += (i ? ", " : "") + names[i];
    }
    const std::string locus = ring.order().to_string(ring.variable_names());
    switch (format) {
    case OutputFormat::sympy:
        if (kind == MonomialOrder::Kind::lex || kind == MonomialOrder::Kind::grlex ||
            kind == MonomialOrder::Kind::grevlex) {
            return "# a reduced basis under order='" + locus + "': groebner(G, " + vars +
                   ", order='" + locus + "')";
        }
        break;
    case OutputFormat::maple:
        if (kind == MonomialOrder::Kind::lex) {
            return "# a reduced basis under plex(" + vars + "): Groebner[Basis](G, plex(" + vars +
                   "))";
        }
        if (kind == MonomialOrder::Kind::grevlex) {
            return "# a reduced basis under tdeg(" + vars + "): Groebner[Basis](G, tdeg(" + vars +
                   "))";
        }
        if (kind == MonomialOrder::Kind::grlex) {
            return "# a reduced basis under grlex(" + vars + "): Groebner[Basis](G, grlex(" + vars +
                   "))";
        }
        break;
    case OutputFormat::mathematica: {
        const char* name = kind == MonomialOrder::Kind::lex       ? "Lexicographic"
                           : kind == MonomialOrder::Kind::grlex   ? "DegreeLexicographic"
                           : kind == MonomialOrder::Kind::grevlex ? "DegreeReverseLexicographic"
                                                                  : nullptr;
        if (name != nullptr) {
            return "(* a reduced basis under GroebnerBasis[G, {" + vars + "}, MonomialOrder -> " +
                   name + "] *)";
        }
        break;
    }
    default:
        break;
    }
    return std::string(format == OutputFormat::mathematica ? "(* " : "# ") +
           "computed under the order " + locus + (format == OutputFormat::mathematica ? " *)" : "");
}

}  // namespace

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
    case OutputFormat::singular: {
        const SystemNames n = system_names(ring, format, {"r", ideal_name});
        out = n.note + singular_ring_named(ring, "r", characteristic, n.names) + "\nideal " +
              std::string(ideal_name) + " =";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n  " : "\n  ") + plain_polynomial(polys[i], n.names);
        }
        if (polys.empty()) {
            out += " 0";
        }
        return out + ";\n";
    }
    case OutputFormat::macaulay2: {
        const SystemNames n = system_names(ring, format, {"R", ideal_name});
        out = n.note + macaulay2_ring(ring, characteristic, n.names) + "\n" +
              std::string(ideal_name) + " = ideal(";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n  " : "\n  ") + plain_polynomial(polys[i], n.names);
        }
        if (polys.empty()) {
            out += "0_R";
        }
        return out + ")\n";
    }
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
    case OutputFormat::sympy: {
        // The Python variables are renamed where they clash; the symbols keep their names.
        const SystemNames n = system_names(ring, format, {ideal_name});
        std::string python_names, symbol_names;
        for (std::size_t i = 0; i < ring.num_vars(); ++i) {
            python_names += (i ? ", " : "") + n.names[i];
            symbol_names += (i ? " " : "") + ring.variable_name(i);
        }
        out = n.note + "from sympy import Rational, symbols\n" + python_names +
              (ring.num_vars() == 1 ? "," : "") + " = symbols('" + symbol_names + "')\n";
        if (characteristic != 0) {
            out += "# coefficients modulo " + std::to_string(characteristic) +
                   ": groebner(G, ..., modulus=" + std::to_string(characteristic) + ")\n";
        }
        out += order_comment(ring, format, n.names) + "\n" + std::string(ideal_name) + " = [";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n    " : "\n    ") + sympy_polynomial(polys[i], n.names);
        }
        return out + (polys.empty() ? "]\n" : "\n]\n");
    }
    case OutputFormat::maple: {
        const SystemNames n = system_names(ring, format, {ideal_name});
        if (characteristic != 0) {
            out += "# coefficients modulo " + std::to_string(characteristic) +
                   ": Groebner[Basis](G, tdeg(...), characteristic = " +
                   std::to_string(characteristic) + ")\n";
        }
        out += order_comment(ring, format, n.names) + "\n" + std::string(ideal_name) + " := [";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n  " : "\n  ") + plain_polynomial(polys[i], n.names);
        }
        return out + "];\n";
    }
    case OutputFormat::mathematica: {
        const SystemNames n = system_names(ring, format, {ideal_name});
        out = n.note;
        if (characteristic != 0) {
            out += "(* coefficients modulo " + std::to_string(characteristic) +
                   ": GroebnerBasis[G, vars, Modulus -> " + std::to_string(characteristic) +
                   "] *)\n";
        }
        out += order_comment(ring, format, n.names) + "\n" + std::string(ideal_name) + " = {";
        for (std::size_t i = 0; i < polys.size(); ++i) {
            out += (i ? ",\n  " : "\n  ") + plain_polynomial(polys[i], n.names);
        }
        return out + "};\n";
    }
    }
    return out;
}

std::string format_polynomial(const Polynomial& f, OutputFormat format) {
    switch (format) {
    case OutputFormat::latex:
        return to_latex(f);
    case OutputFormat::sympy:
        return sympy_polynomial(f, f.ring()->variable_names());
    default:
        return to_string(f);
    }
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
