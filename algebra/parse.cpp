#include "algebra/parse.h"

#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "algebra/error.h"

namespace locus::algebra {
namespace {

enum class TokenKind { number, identifier, symbol, end };

struct Token {
    TokenKind kind = TokenKind::end;
    std::string text;
    std::size_t line = 1, column = 1;
};

// A token as messages quote it: control characters (a NUL byte would end the message) and
// bytes that are not UTF-8 by their code, e.g. 'U+0000' or 'byte 0xFF'.
std::string describe(const Token& t) {
    if (t.kind == TokenKind::end) {
        return "end of input";
    }
    const auto first = static_cast<unsigned char>(t.text[0]);
    char code[32];
    if (first < 0x20 || first == 0x7F) {
        std::snprintf(code, sizeof code, "U+%04X (a control character)", first);
        return code;
    }
    if (first >= 0x80 && (t.text.size() == 1 || first < 0xC0)) {
        std::snprintf(code, sizeof code, "byte 0x%02X (not UTF-8 text)", first);
        return code;
    }
    if (first < 0x80) {
        return "'" + t.text + "'";
    }
    // A non-ASCII character: name its code point too, since it may be invisible (a byte-order
    // mark, a zero-width or no-break space) or look like an ASCII one.
    const std::size_t length = first >= 0xF0 ? 4 : first >= 0xE0 ? 3 : 2;
    std::uint32_t point = first & (0x3F >> (length - 1));
    for (std::size_t i = 1; i < length && i < t.text.size(); ++i) {
        point = (point << 6) | (static_cast<unsigned char>(t.text[i]) & 0x3F);
    }
    std::snprintf(code, sizeof code, " (U+%04X)", static_cast<unsigned>(point));
    return "'" + t.text.substr(0, length) + "'" + code;
}

class Lexer {
  public:
    Lexer(std::string_view text, std::size_t line, std::size_t column)
        : text_(text), line_(line), column_(column) {}

    Token next() {
        skip_space();
        Token t;
        t.line = line_;
        t.column = column_;
        if (pos_ >= text_.size()) {
            return t;
        }
        const char c = text_[pos_];
        const auto is_digit = [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); };
        if (is_digit(c) || (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))) {
            t.kind = TokenKind::number;
            while (pos_ < text_.size() && (is_digit(text_[pos_]) || text_[pos_] == '.')) {
                advance();
            }
            // A decimal exponent, as numerical tools print numbers: 1.5e-3. Only when digits
            // follow (after a sign): "2e" stays the number 2 and the name e, an error as before.
            if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
                std::size_t digits_at = pos_ + 1;
                if (digits_at < text_.size() &&
                    (text_[digits_at] == '+' || text_[digits_at] == '-')) {
                    ++digits_at;
                }
                if (digits_at < text_.size() && is_digit(text_[digits_at])) {
                    while (pos_ < digits_at) {
                        advance();
                    }
                    while (pos_ < text_.size() && is_digit(text_[pos_])) {
                        advance();
                    }
                }
            }
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            t.kind = TokenKind::identifier;
            while (pos_ < text_.size() &&
                   (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
                advance();
            }
        } else {
            // A symbol; a non-ASCII character is taken whole (all its UTF-8 bytes), so that
            // messages show '²' rather than half of it.
            t.kind = TokenKind::symbol;
            advance();
            if (c == '*' && pos_ < text_.size() && text_[pos_] == '*') {
                // Python's and SymPy's power: the same token as '^' (messages name it '^').
                advance();
                t.text = "^";
                return t;
            }
            const auto byte = static_cast<unsigned char>(c);
            std::size_t continuation = byte >= 0xF0 ? 3 : byte >= 0xE0 ? 2 : byte >= 0xC0 ? 1 : 0;
            while (continuation-- > 0 && pos_ < text_.size() &&
                   (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) {
                ++pos_;  // the character counts as one column
            }
            t.text = std::string(text_.substr(start_, pos_ - start_));
            return t;
        }
        t.text = std::string(text_.substr(start_, pos_ - start_));
        return t;
    }

  private:
    void skip_space() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            advance();
        }
        start_ = pos_;
    }
    void advance() {
        if (text_[pos_] == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        ++pos_;
    }

    std::string_view text_;
    std::size_t pos_ = 0, start_ = 0;
    std::size_t line_, column_;
};

// Division in the two value types: polynomials only by non-zero constants, rational functions
// by anything non-zero.
Polynomial divide(const Polynomial& p, const Polynomial& q, const Token& divisor_start) {
    if (!q.is_constant()) {
        throw ParseError(divisor_start.line, divisor_start.column,
                         "a constant divisor (division only by numbers)", describe(divisor_start));
    }
    if (q.is_zero()) {
        throw ParseError(divisor_start.line, divisor_start.column, "a non-zero divisor",
                         describe(divisor_start));
    }
    Rational inverse;
    fmpq_inv(inverse.get(), q.leading_coefficient().get());
    return p * inverse;
}

RationalFunction divide(const RationalFunction& p, const RationalFunction& q,
                        const Token& divisor_start) {
    if (q.is_zero()) {
        throw ParseError(divisor_start.line, divisor_start.column, "a non-zero divisor",
                         describe(divisor_start) + " (the divisor is identically zero)");
    }
    return p / q;
}

// The most work one expression may take to expand, in the unit of kMaxPowerWork (products of
// 64-bit limbs): about a second, as much as one power may take. Each operation is bounded on
// its own too, but an expression can chain hundreds of them ((1-t)^126*(1-s)^9*... over many
// terms, a fuzzer's timeout; at 3e7 the refusal itself took 11 s under the sanitizers).
constexpr double kMaxExpressionWork = kMaxPowerWork;

// Limb products of a·b: every pair of terms, weighted by the limbs of the wider coefficients.
double multiplication_work(const Polynomial& a, const Polynomial& b) {
    return static_cast<double>(a.num_terms()) * static_cast<double>(b.num_terms()) *
           (1.0 + (a.widest_coefficient_bits() + b.widest_coefficient_bits()) / 64.0);
}

// The work of the arithmetic steps in the two value types. Polynomial sums merge (linear, not
// counted); rational functions cross-multiply.
double product_work(const Polynomial& a, const Polynomial& b) {
    return multiplication_work(a, b);
}
double product_work(const RationalFunction& a, const RationalFunction& b) {
    return multiplication_work(a.numerator(), b.numerator()) +
           multiplication_work(a.denominator(), b.denominator());
}
double quotient_work(const Polynomial& a, const Polynomial&) {
    return static_cast<double>(a.num_terms());
}
double quotient_work(const RationalFunction& a, const RationalFunction& b) {
    return multiplication_work(a.numerator(), b.denominator()) +
           multiplication_work(a.denominator(), b.numerator());
}
double sum_work(const Polynomial&, const Polynomial&) {
    return 0.0;
}
double sum_work(const RationalFunction& a, const RationalFunction& b) {
    if (a.denominator() == b.denominator()) {
        return 0.0;
    }
    return multiplication_work(a.numerator(), b.denominator()) +
           multiplication_work(b.numerator(), a.denominator()) +
           multiplication_work(a.denominator(), b.denominator());
}
// A power is bounded on its own before it is expanded (Polynomial::pow); afterwards it counts
// about as much as its last multiplication, a quarter of squaring the result.
double power_work(const Polynomial& result) {
    return multiplication_work(result, result) / 4.0;
}
double power_work(const RationalFunction& result) {
    return power_work(result.numerator()) + power_work(result.denominator());
}

// Recursive descent over:  sum := product (('+'|'-') product)*
//   product := unary (('*'|'/') unary)*   unary := ('+'|'-') unary | power
//   power := atom (('^'|'**') integer)?   atom := number | variable | '(' sum ')'
template <class Value>
class InfixParser {
  public:
    InfixParser(std::string_view text, const RingPtr& ring, std::size_t line, std::size_t column,
                Trigonometry* trigonometry = nullptr)
        : lexer_(text, line, column), ring_(ring), trigonometry_(trigonometry) {
        token_ = lexer_.next();
        if (trigonometry_ != nullptr) {
            trigonometry_->inside.resize(ring_->num_vars());
            trigonometry_->outside.resize(ring_->num_vars());
        }
    }

    Value parse() {
        if (token_.kind == TokenKind::end) {
            fail("a polynomial");
        }
        Value p = sum();
        if (token_.kind != TokenKind::end) {
            fail(token_.text == ")" ? "end of input (unbalanced ')')"
                                    : "an operator (+ - * / ^) or end of input");
        }
        return p;
    }

  private:
    // Counts the work of a step about to run (or just run, for a power) against
    // kMaxExpressionWork.
    void charge(double work, std::size_t line, std::size_t column) {
        work_ += work;
        if (work_ > kMaxExpressionWork) {
            throw ResourceLimit("line " + std::to_string(line) + ", column " +
                                std::to_string(column) + ": the expression would take more than " +
                                std::to_string(static_cast<long>(kMaxExpressionWork)) +
                                " limb products to expand (the limit)");
        }
    }

    [[noreturn]] void fail(const std::string& expected) {
        throw ParseError(token_.line, token_.column, expected, describe(token_));
    }
    bool is_symbol(char c) const { return token_.kind == TokenKind::symbol && token_.text[0] == c; }
    // Runs an arithmetic step, reporting exponent overflow at the operator.
    template <class F>
    Value guarded(const Token& op, F&& step) {
        try {
            return step();
        } catch (const ExponentOverflow&) {
            throw ParseError(
                op.line, op.column,
                "exponents of at most " + std::to_string(MonomialLayout::max_field_value),
                "a product that overflows them");
        }
    }

    // The summands are added pairwise, as in merge sort: adding them left to right merged the
    // whole partial sum at every '+', quadratic in the terms (a 60 000-term line took 22 s).
    Value sum() {
        const std::size_t start_line = token_.line, start_column = token_.column;
        std::vector<Value> summands;
        summands.push_back(product());
        while (is_symbol('+') || is_symbol('-')) {
            const bool minus = is_symbol('-');
            token_ = lexer_.next();
            Value q = product();
            summands.push_back(minus ? -q : std::move(q));
        }
        while (summands.size() > 1) {
            std::vector<Value> halved;
            halved.reserve((summands.size() + 1) / 2);
            for (std::size_t i = 0; i + 1 < summands.size(); i += 2) {
                charge(sum_work(summands[i], summands[i + 1]), start_line, start_column);
                halved.push_back(summands[i] + summands[i + 1]);
            }
            if (summands.size() % 2 == 1) {
                halved.push_back(std::move(summands.back()));
            }
            summands = std::move(halved);
        }
        return std::move(summands.front());
    }

    Value product() {
        Value p = unary();
        while (is_symbol('*') || is_symbol('/')) {
            const Token op = token_;
            token_ = lexer_.next();
            const Token divisor_start = token_;
            Value q = unary();
            if (op.text == "*") {
                charge(product_work(p, q), op.line, op.column);
                p = guarded(op, [&] { return p * q; });
            } else {
                charge(quotient_work(p, q), op.line, op.column);
                p = divide(p, q, divisor_start);
            }
        }
        return p;
    }

    // Signs in a loop, not by recursion: twenty thousand unary minuses are input, not a
    // reason to overflow the stack.
    Value unary() {
        bool negative = false;
        while (is_symbol('-') || is_symbol('+')) {
            negative = negative != is_symbol('-');
            token_ = lexer_.next();
        }
        Value p = power();
        return negative ? -p : p;
    }

    Value power() {
        Value base = atom();
        if (!is_symbol('^')) {
            return base;
        }
        const Token op = token_;
        token_ = lexer_.next();
        const std::string expected = "a non-negative integer exponent";
        if (token_.kind != TokenKind::number ||
            token_.text.find_first_of(".eE") != std::string::npos) {
            fail(expected);
        }
        const std::string digits = token_.text;
        const std::uint32_t limit = MonomialLayout::max_field_value;
        if (digits.size() > 9 || std::stoul(digits) > limit) {
            fail("an exponent of at most " + std::to_string(limit));
        }
        const auto k = static_cast<unsigned>(std::stoul(digits));
        const Token exponent_token = token_;
        token_ = lexer_.next();
        if (is_symbol('^')) {
            fail("no second '^' (write (a^b)^c)");
        }
        // Refusals inside pow() point at the power; its work counts once it is done.
        Value result = [&] {
            try {
                return base.pow(k);
            } catch (const ExponentOverflow&) {
                throw ParseError(exponent_token.line, exponent_token.column,
                                 "an exponent of at most " + std::to_string(limit),
                                 "'" + digits + "' (the power overflows)");
            } catch (const ResourceLimit& refused) {
                throw ResourceLimit("line " + std::to_string(op.line) + ", column " +
                                    std::to_string(op.column) + ": " + refused.what());
            }
        }();
        charge(power_work(result), op.line, op.column);
        return result;
    }

    Value atom() {
        if (token_.kind == TokenKind::number) {
            Rational value;
            if (!Rational::from_literal(token_.text, value)) {
                fail("a number such as 12, 3.5, 0.125 or 1.5e-3 (decimal exponents of at most " +
                     std::to_string(Rational::kMaxDecimalExponent) + ")");
            }
            token_ = lexer_.next();
            return Value::constant(ring_, std::move(value));
        }
        if (token_.kind == TokenKind::identifier) {
            const auto var = ring_->variable_index(token_.text);
            if (!var && (token_.text == "sin" || token_.text == "cos")) {
                return trigonometric();
            }
            if (!var) {
                fail("a declared variable");
            }
            note_use(trigonometry_ != nullptr ? &trigonometry_->outside : nullptr, *var);
            token_ = lexer_.next();
            return Value::variable(ring_, *var);
        }
        if (is_symbol('(')) {
            const Token open = token_;
            if (++depth_ > kMaxNesting) {
                fail("parentheses nested at most " + std::to_string(kMaxNesting) + " deep");
            }
            token_ = lexer_.next();
            Value p = sum();
            --depth_;
            if (!is_symbol(')')) {
                fail("')' to close the '(' at column " + std::to_string(open.column));
            }
            token_ = lexer_.next();
            return p;
        }
        fail("a number, a variable or '('");
    }

    void note_use(std::vector<Trigonometry::Use>* uses, std::size_t var) {
        if (uses != nullptr && var < uses->size() && (*uses)[var].line == 0) {
            (*uses)[var] = {token_.line, token_.column};
        }
    }

    // sin(θ) or cos(θ) with θ an integer combination of variables: term (('+'|'-') term)*,
    // term := ['+'|'-'] (integer '*' variable | variable ['*' integer]).
    Value trigonometric() {
        const Token function = token_;
        if constexpr (!std::is_same_v<Value, RationalFunction>) {
            fail("a declared variable (" + function.text + " is not a polynomial)");
        } else {
            if (trigonometry_ == nullptr) {
                fail("a declared variable (" + function.text + " is not allowed here)");
            }
            const std::string expected_angle =
                "an integer combination of parameters (sin and cos take, for example, u, 2*u or "
                "u-v)";
            token_ = lexer_.next();
            if (!is_symbol('(')) {
                fail("'(' after " + function.text);
            }
            token_ = lexer_.next();
            std::vector<long> multiple(ring_->num_vars(), 0);
            bool first = true;
            while (first || is_symbol('+') || is_symbol('-')) {
                long sign = 1;
                if (is_symbol('+') || is_symbol('-')) {
                    sign = is_symbol('-') ? -1 : 1;
                    token_ = lexer_.next();
                }
                first = false;
                long factor = 1;
                if (token_.kind == TokenKind::number) {
                    factor = small_integer(expected_angle);
                    token_ = lexer_.next();
                    if (!is_symbol('*')) {
                        fail(expected_angle);
                    }
                    token_ = lexer_.next();
                }
                const auto var = token_.kind == TokenKind::identifier
                                     ? ring_->variable_index(token_.text)
                                     : std::nullopt;
                if (!var) {
                    fail(expected_angle);
                }
                note_use(&trigonometry_->inside, *var);
                token_ = lexer_.next();
                if (is_symbol('*')) {
                    token_ = lexer_.next();
                    if (token_.kind != TokenKind::number) {
                        fail(expected_angle);
                    }
                    factor *= small_integer(expected_angle);
                    token_ = lexer_.next();
                }
                multiple[*var] += sign * factor;
            }
            if (!is_symbol(')')) {
                fail(
                    "')' or '+'/'-' and a further multiple of a parameter (sin and cos take an "
                    "integer combination of parameters)");
            }
            token_ = lexer_.next();
            return function.text == "cos" ? angle(multiple).first : angle(multiple).second;
        }
    }

    // An integer literal of at most 1000 (the multiple of an angle).
    long small_integer(const std::string& expected) {
        if (token_.text.find_first_of(".eE") != std::string::npos || token_.text.size() > 4 ||
            std::stol(token_.text) > 1000) {
            fail(expected + ", with multiples of at most 1000");
        }
        return std::stol(token_.text);
    }

    // cos θ and sin θ for θ = Σ multiple[v]·v, as the real and imaginary parts of
    // Π e^{i·k·v} (conjugates for negative k).
    std::pair<RationalFunction, RationalFunction> angle(const std::vector<long>& multiple) {
        const Polynomial one = Polynomial::constant(ring_, Rational(1));
        Polynomial re = one, im(ring_), denominator = one;
        auto times = [&](const Polynomial& a, const Polynomial& b) {
            charge(multiplication_work(re, a) + multiplication_work(im, b) +
                       multiplication_work(re, b) + multiplication_work(im, a),
                   token_.line, token_.column);
            // (re + i·im)·(a + i·b)
            Polynomial next_re = re * a - im * b;
            im = re * b + im * a;
            re = std::move(next_re);
        };
        for (std::size_t v = 0; v < multiple.size(); ++v) {
            const long k = multiple[v];
            if (k == 0) {
                continue;
            }
            const Rational sign(k > 0 ? 1 : -1);
            if (trigonometry_->form == Trigonometry::Form::half_angle) {
                const Polynomial t = Polynomial::variable(ring_, v);
                for (long j = 0; j < 2 * std::abs(k); ++j) {
                    times(one, sign * t);  // (1 ± i·t)^(2|k|)
                }
                denominator *= (one + t * t).pow(static_cast<unsigned>(std::abs(k)));
            } else {
                const Polynomial c = Polynomial::variable(ring_, trigonometry_->cos_of.at(v));
                const Polynomial s = Polynomial::variable(ring_, trigonometry_->sin_of.at(v));
                for (long j = 0; j < std::abs(k); ++j) {
                    times(c, sign * s);  // (cos v ± i·sin v)^|k|
                }
            }
        }
        return {RationalFunction(re, denominator), RationalFunction(im, denominator)};
    }

    Lexer lexer_;
    int depth_ = 0;      // parentheses open
    double work_ = 0.0;  // of the arithmetic so far (charge)
    const RingPtr& ring_;
    Trigonometry* trigonometry_;
    Token token_;
};

std::string_view trim(std::string_view s, std::size_t* leading = nullptr) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) {
        ++a;
    }
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) {
        --b;
    }
    if (leading) {
        *leading = a;
    }
    return s.substr(a, b - a);
}

}  // namespace

Polynomial parse_polynomial(std::string_view text, const RingPtr& ring, std::size_t line,
                            std::size_t first_column) {
    return InfixParser<Polynomial>(text, ring, line, first_column).parse();
}

RationalFunction parse_rational_function(std::string_view text, const RingPtr& ring,
                                         std::size_t line, std::size_t first_column,
                                         Trigonometry* trigonometry) {
    return InfixParser<RationalFunction>(text, ring, line, first_column, trigonometry).parse();
}

std::vector<std::string> parse_name_list(std::string_view text, std::size_t line,
                                         std::size_t first_column) {
    std::vector<std::string> names;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        std::size_t lead = 0;
        const std::string_view name = trim(text.substr(start, comma - start), &lead);
        const std::size_t column = first_column + start + lead;
        const bool ok = !name.empty() &&
                        (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
                        std::all_of(name.begin(), name.end(), [](char c) {
                            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                        });
        if (!ok) {
            throw ParseError(line, column, "a variable name (an identifier)",
                             name.empty() ? std::string("nothing") : "'" + std::string(name) + "'");
        }
        if (std::find(names.begin(), names.end(), name) != names.end()) {
            throw ParseError(line, column, "a name not declared before",
                             "'" + std::string(name) + "' a second time");
        }
        names.emplace_back(name);
        if (comma == text.size()) {
            break;
        }
        start = comma + 1;
    }
    return names;
}

std::vector<SourceLine> split_lines(std::string_view text) {
    std::vector<SourceLine> lines;
    std::size_t pos = 0;
    while (true) {
        const std::size_t eol = std::min(text.find('\n', pos), text.size());
        std::string_view raw = text.substr(pos, eol - pos);
        if (const auto hash = raw.find('#'); hash != std::string_view::npos) {
            raw = raw.substr(0, hash);
        }
        lines.push_back({raw, lines.size() + 1});
        if (eol == text.size()) {
            return lines;
        }
        pos = eol + 1;
    }
}

namespace {

// The first two non-blank lines of a text (number 0: there is none), and where each ends.
struct HeaderLine {
    std::string_view text;
    std::size_t number = 0;
    std::size_t end = 0;  // offset just past its newline
};
std::array<HeaderLine, 2> first_nonblank_lines(std::string_view text) {
    std::array<HeaderLine, 2> found{};
    std::size_t count = 0, pos = 0, number = 1;
    while (count < 2 && pos < text.size()) {
        const std::size_t eol = std::min(text.find('\n', pos), text.size());
        const std::string_view line = text.substr(pos, eol - pos);
        pos = std::min(eol + 1, text.size());
        if (!trim(line).empty()) {
            found[count++] = {line, number, pos};
        }
        ++number;
    }
    return found;
}

// `characteristic:`'s value, or msolve's second line: 0 or a prime below 2³¹.
std::uint32_t parse_characteristic(std::string_view value, std::size_t line, std::size_t column) {
    std::size_t lead = 0;
    const std::string_view digits = trim(value, &lead);
    const std::string expected = "the characteristic: 0 or a prime below 2^31";
    if (digits.empty()) {
        throw ParseError(line, column + lead, expected, "nothing");
    }
    std::uint64_t p = 0;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(digits[i]))) {
            throw ParseError(line, column + lead + i, expected,
                             "'" + std::string(digits.substr(i, 12)) + "'");
        }
        p = p * 10 + static_cast<std::uint64_t>(digits[i] - '0');
        if (p >= (std::uint64_t{1} << 31)) {
            throw ParseError(line, column + lead, expected, "a number of 2^31 or more");
        }
    }
    if (p != 0 && !n_is_prime(p)) {
        throw ParseError(line, column + lead, expected, std::to_string(p) + ", not a prime");
    }
    return static_cast<std::uint32_t>(p);
}

// In characteristic p, a coefficient stands for its residue: refuses a denominator divisible
// by p (1/5 in characteristic 5 has no residue), at the generator's position.
void check_residues(const Polynomial& f, std::uint32_t p, std::size_t line, std::size_t column) {
    if (p == 0) {
        return;
    }
    for (std::size_t i = 0; i < f.num_terms(); ++i) {
        if (fmpz_fdiv_ui(fmpq_denref(f.coefficient(i).get()), p) == 0) {
            throw ParseError(line, column,
                             "coefficients whose denominators are not divisible by the "
                             "characteristic " +
                                 std::to_string(p),
                             f.coefficient(i).to_string());
        }
    }
}

// A generator line of an ideal file (comments removed), and a generator's whole text.
struct PendingLine {
    std::string_view text;
    std::size_t line, column;
};
struct GeneratorText {
    std::string text;  // lines joined by '\n', so that the lexer keeps lines and columns
    std::size_t line, column;
};

// The generators of an ideal file: a generator continues on the next line while a parenthesis
// is open or its line ends with an operator (+ - * / ^); commas outside parentheses separate
// generators (a line may hold several, and a trailing comma only ends one).
std::vector<GeneratorText> join_generator_lines(const std::vector<PendingLine>& lines) {
    std::vector<GeneratorText> out;
    GeneratorText current{{}, 0, 0};
    bool open = false;  // `current` has begun
    int depth = 0;
    const auto finish = [&] {
        // Blank lines it ran over at its end are not part of it: an unclosed parenthesis is
        // reported where the text ends, not on a line after it.
        while (!current.text.empty() &&
               std::isspace(static_cast<unsigned char>(current.text.back()))) {
            current.text.pop_back();
        }
        if (open && !current.text.empty()) {
            out.push_back(current);
        }
        open = false;
        current.text.clear();
    };
    for (const PendingLine& pending : lines) {
        if (open) {
            current.text += '\n';
        }
        std::size_t column = pending.column;
        for (const char c : pending.text) {
            if (!open) {
                if (std::isspace(static_cast<unsigned char>(c))) {
                    ++column;
                    continue;
                }
                // Leading spaces become the column the lexer starts from.
                open = true;
                current.line = pending.line;
                current.column = column;
            }
            if (c == '(') {
                ++depth;
            } else if (c == ')') {
                --depth;
            }
            if (c == ',' && depth <= 0) {
                if (trim(current.text).empty()) {
                    throw ParseError(pending.line, column, "a generator before ','", "','");
                }
                finish();
                depth = 0;
            } else {
                current.text += c;
            }
            ++column;
        }
        const std::string_view tail = open ? trim(current.text) : std::string_view{};
        const bool continues =
            depth > 0 || (!tail.empty() &&
                          std::string_view("+-*/^").find(tail.back()) != std::string_view::npos);
        if (!continues) {
            finish();
            depth = 0;
        }
    }
    finish();
    return out;
}

}  // namespace

IdealFile parse_ideal_file(std::string_view text) {
    IdealFile file;
    std::vector<std::string> names;
    bool have_vars = false, have_characteristic = false;
    std::string order_text = "grevlex";
    std::size_t order_line = 0, order_column = 0;
    std::vector<PendingLine> generator_lines;
    const std::vector<SourceLine> lines = split_lines(text);
    for (const auto& [raw, line_number] : lines) {
        std::size_t lead = 0;
        const std::string_view content = trim(raw, &lead);
        if (content.empty()) {
            if (!generator_lines.empty()) {
                // Kept (empty) among the generators: a generator continued past it keeps the
                // line numbers of the file.
                generator_lines.push_back({std::string_view{}, line_number, 1});
            }
            continue;
        }
        const auto colon = content.find(':');
        if (colon != std::string_view::npos) {
            const std::string_view key = trim(content.substr(0, colon));
            const std::size_t value_column = lead + colon + 2;
            const std::string_view value = raw.substr(lead + colon + 1);
            if (!generator_lines.empty()) {
                throw ParseError(line_number, lead + 1, "a generator (headers come first)",
                                 "'" + std::string(key) + ":'");
            }
            if (key == "vars") {
                if (have_vars) {
                    throw ParseError(line_number, lead + 1, "one 'vars:' line", "a second one");
                }
                names = parse_name_list(value, line_number, value_column);
                have_vars = true;
            } else if (key == "order") {
                order_text = std::string(value);
                order_line = line_number;
                order_column = value_column;
            } else if (key == "characteristic") {
                // A second line is refused, not taken: which of two primes was meant is not
                // for the reader to guess (it once silently used the last).
                if (have_characteristic) {
                    throw ParseError(line_number, lead + 1, "one 'characteristic:' line",
                                     "a second one");
                }
                file.characteristic = parse_characteristic(value, line_number, value_column);
                have_characteristic = true;
            } else {
                throw ParseError(line_number, lead + 1,
                                 "'vars:', 'order:', 'characteristic:' or a generator",
                                 "'" + std::string(key) + ":'");
            }
        } else {
            if (!have_vars) {
                throw ParseError(line_number, lead + 1, "a 'vars:' line before the generators",
                                 "'" + std::string(content.substr(0, 20)) + "'");
            }
            generator_lines.push_back({raw, line_number, 1});
        }
    }
    if (!have_vars) {
        throw ParseError(lines.back().number, 1, "a 'vars:' line", "end of input");
    }
    MonomialOrder order = order_line == 0
                              ? MonomialOrder::grevlex(names.size())
                              : parse_monomial_order(order_text, names, order_line, order_column);
    file.ring = PolyRing::make(names, std::move(order));
    for (const GeneratorText& g : join_generator_lines(generator_lines)) {
        Polynomial p = parse_polynomial(g.text, file.ring, g.line, g.column);
        check_residues(p, file.characteristic, g.line, g.column);
        if (!p.is_zero()) {
            file.generators.push_back(std::move(p));
            file.generator_lines.push_back(g.line);
        }
    }
    return file;
}

IdealFile parse_msolve_file(std::string_view text) {
    IdealFile file;
    // The first two non-blank lines, then the rest of the text.
    const auto header = first_nonblank_lines(text);
    if (header[0].number == 0 || header[1].number == 0) {
        const std::size_t end_line =
            static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
        throw ParseError(
            end_line, 1,
            header[0].number == 0 ? "the variables (msolve format)" : "the characteristic",
            "end of input");
    }
    std::size_t pos = header[1].end, line = header[1].number + 1;
    const std::vector<std::string> names = parse_name_list(header[0].text, header[0].number, 1);
    file.characteristic = parse_characteristic(header[1].text, header[1].number, 1);
    file.ring = PolyRing::make(names, MonomialOrder::grevlex(names.size()));
    // The polynomials: pieces between commas, each parsed where it starts.
    std::size_t piece_start = std::min(pos, text.size()), piece_line = line, piece_column = 1;
    std::size_t column = 1;
    bool any = false;
    const auto finish_piece = [&](std::size_t end, bool last) {
        const std::string_view piece = text.substr(piece_start, end - piece_start);
        if (trim(piece).empty()) {
            if (last && !any) {
                throw ParseError(piece_line, piece_column, "a polynomial after the characteristic",
                                 "end of input");
            }
            throw ParseError(piece_line, piece_column, "a polynomial",
                             last ? "end of input" : "','");
        }
        Polynomial p = parse_polynomial(piece, file.ring, piece_line, piece_column);
        check_residues(p, file.characteristic, piece_line, piece_column);
        if (!p.is_zero()) {
            file.generators.push_back(std::move(p));
            file.generator_lines.push_back(piece_line);
        }
        any = true;
    };
    for (std::size_t i = piece_start; i < text.size(); ++i) {
        if (text[i] == ',') {
            finish_piece(i, false);
            piece_start = i + 1;
            piece_line = line;
            piece_column = column + 1;
        }
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    finish_piece(text.size(), true);
    return file;
}

bool looks_like_msolve(std::string_view text) {
    const auto first = first_nonblank_lines(text);
    const std::string_view characteristic = trim(first[1].text);
    return first[1].number != 0 && first[0].text.find(':') == std::string_view::npos &&
           std::all_of(characteristic.begin(), characteristic.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

}  // namespace locus::algebra
