#include "algebra/system_input.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algebra/error.h"
#include "algebra/monomial_order.h"

namespace locus::algebra {
namespace {

// The text with comments blanked out (newlines kept), so that every offset keeps its line and
// column. Singular: // and /* */; Macaulay2: -- and -* *-.
std::string without_comments(std::string_view text, bool singular) {
    std::string out(text);
    const char* line_comment = singular ? "//" : "--";
    const char* open = singular ? "/*" : "-*";
    const char* close = singular ? "*/" : "*-";
    bool in_string = false;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (out[i] == '"') {
            in_string = !in_string;
        }
        if (in_string) {
            continue;
        }
        if (out.compare(i, 2, line_comment) == 0) {
            while (i < out.size() && out[i] != '\n') {
                out[i++] = ' ';
            }
        } else if (out.compare(i, 2, open) == 0) {
            const std::size_t end = out.find(close, i + 2);
            const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
            for (; i < stop; ++i) {
                if (out[i] != '\n') {
                    out[i] = ' ';
                }
            }
            --i;
        }
    }
    return out;
}

// Offsets of a text as lines and columns (1-based).
class Positions {
  public:
    explicit Positions(std::string_view text) {
        starts_.push_back(0);
        for (std::size_t i = 0; i < text.size(); ++i) {
            if (text[i] == '\n') {
                starts_.push_back(i + 1);
            }
        }
    }
    std::size_t line(std::size_t offset) const {
        return static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), offset) -
                                        starts_.begin());
    }
    std::size_t column(std::size_t offset) const { return offset - starts_[line(offset) - 1] + 1; }

  private:
    std::vector<std::size_t> starts_;
};

// A piece of the text: [begin, end).
struct Span {
    std::size_t begin = 0, end = 0;
};

bool is_space(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

Span trimmed(std::string_view text, Span s) {
    while (s.begin < s.end && is_space(text[s.begin])) {
        ++s.begin;
    }
    while (s.end > s.begin && is_space(text[s.end - 1])) {
        --s.end;
    }
    return s;
}

class Reader {
  public:
    Reader(std::string_view text) : text_(text), positions_(text) {}

    std::string_view view(Span s) const { return text_.substr(s.begin, s.end - s.begin); }

    [[noreturn]] void fail(std::size_t offset, const std::string& expected,
                           const std::string& found) const {
        throw ParseError(positions_.line(offset), positions_.column(offset), expected, found);
    }
    std::string found_at(std::size_t offset) const {
        if (offset >= text_.size()) {
            return "end of input";
        }
        std::size_t end = offset + 1;
        while (end < text_.size() && end - offset < 16 && !is_space(text_[end])) {
            ++end;
        }
        std::string quoted = "'";
        quoted.append(text_.data() + offset, end - offset);
        quoted.push_back('\'');
        return quoted;
    }

    // Pieces between commas outside brackets.
    std::vector<Span> split_commas(Span s) const {
        std::vector<Span> pieces;
        int depth = 0;
        std::size_t start = s.begin;
        for (std::size_t i = s.begin; i < s.end; ++i) {
            const char c = text_[i];
            if (c == '(' || c == '[' || c == '{') {
                ++depth;
            } else if (c == ')' || c == ']' || c == '}') {
                --depth;
            } else if (c == ',' && depth == 0) {
                pieces.push_back(trimmed(text_, {start, i}));
                start = i + 1;
            }
        }
        pieces.push_back(trimmed(text_, {start, s.end}));
        return pieces;
    }

    // The offset just past the bracket that closes the one at `open`.
    std::size_t closing(std::size_t open) const {
        const char o = text_[open];
        const char c = o == '(' ? ')' : o == '[' ? ']' : '}';
        int depth = 0;
        for (std::size_t i = open; i < text_.size(); ++i) {
            if (text_[i] == o) {
                ++depth;
            } else if (text_[i] == c && --depth == 0) {
                return i + 1;
            }
        }
        fail(open, std::string("a closing '") + c + "'", "end of input");
    }

    std::vector<std::string> names(Span s) const {
        return parse_name_list(view(s), positions_.line(s.begin), positions_.column(s.begin));
    }

    std::int64_t integer(Span s, const char* what) const {
        const std::string_view digits = view(trimmed(text_, s));
        std::size_t i = digits.size() > 0 && digits[0] == '-' ? 1 : 0;
        if (digits.size() == i || digits.size() > 12) {
            fail(s.begin, what, found_at(s.begin));
        }
        for (std::size_t k = i; k < digits.size(); ++k) {
            if (!std::isdigit(static_cast<unsigned char>(digits[k]))) {
                fail(s.begin + k, what, found_at(s.begin + k));
            }
        }
        return std::stoll(std::string(digits));
    }

    std::vector<std::int64_t> integers(Span s, const char* what) const {
        std::vector<std::int64_t> out;
        for (const Span piece : split_commas(s)) {
            out.push_back(integer(piece, what));
        }
        return out;
    }

    // Characteristic 0 or a prime below 2³¹.
    std::uint32_t characteristic(Span s) const {
        const std::int64_t p = integer(s, "the characteristic: 0 or a prime below 2^31");
        if (p < 0 || p >= (std::int64_t{1} << 31) ||
            (p != 0 && !n_is_prime(static_cast<ulong>(p)))) {
            fail(s.begin, "the characteristic: 0 or a prime below 2^31", found_at(s.begin));
        }
        return static_cast<std::uint32_t>(p);
    }

    // The generators of a list, each parsed where it stands.
    void generators(Span list, IdealFile& file) const {
        for (const Span piece : split_commas(list)) {
            if (piece.begin == piece.end) {
                fail(piece.begin, "a polynomial", found_at(piece.begin));
            }
            const std::size_t line = positions_.line(piece.begin);
            const std::size_t column = positions_.column(piece.begin);
            Polynomial p = parse_polynomial(view(piece), file.ring, line, column);
            if (p.is_zero()) {
                continue;
            }
            if (file.characteristic != 0) {
                for (std::size_t i = 0; i < p.num_terms(); ++i) {
                    if (fmpz_fdiv_ui(fmpq_denref(p.coefficient(i).get()), file.characteristic) ==
                        0) {
                        fail(piece.begin, "a coefficient with a residue modulo the characteristic",
                             p.coefficient(i).to_string());
                    }
                }
            }
            file.generators.push_back(std::move(p));
            file.generator_lines.push_back(line);
        }
    }

    std::size_t skip_space(std::size_t i) const {
        while (i < text_.size() && is_space(text_[i])) {
            ++i;
        }
        return i;
    }
    bool word_at(std::size_t i, std::string_view word) const {
        return text_.compare(i, word.size(), word) == 0 &&
               (i + word.size() >= text_.size() ||
                !(std::isalnum(static_cast<unsigned char>(text_[i + word.size()])) ||
                  text_[i + word.size()] == '_')) &&
               (i == 0 ||
                !(std::isalnum(static_cast<unsigned char>(text_[i - 1])) || text_[i - 1] == '_'));
    }
    std::size_t size() const { return text_.size(); }
    char at(std::size_t i) const { return i < text_.size() ? text_[i] : '\0'; }

  private:
    std::string_view text_;
    Positions positions_;
};

// Singular's order of a ring with `n` variables: lp, dp, Dp, wp(..), M(..), and block orders
// (dp(k),dp(m)) as elimination of the first k variables; module components (c, C) are ignored.
MonomialOrder singular_order(const Reader& r, Span s, std::size_t n) {
    const std::string_view o = r.view(s);
    const auto argument = [&](std::size_t name_length) {
        if (r.at(s.begin + name_length) != '(' || r.at(s.end - 1) != ')') {
            r.fail(s.begin + name_length, "'(' and the order's arguments ')'",
                   r.found_at(s.begin + name_length));
        }
        return Span{s.begin + name_length + 1, s.end - 1};
    };
    if (o == "lp") {
        return MonomialOrder::lex(n);
    }
    if (o == "dp") {
        return MonomialOrder::grevlex(n);
    }
    if (o == "Dp") {
        return MonomialOrder::grlex(n);
    }
    if (o.starts_with("wp")) {
        const auto weights = r.integers(argument(2), "a weight");
        if (weights.size() != n) {
            r.fail(s.begin, "one weight per variable (" + std::to_string(n) + ")",
                   std::to_string(weights.size()) + " weights");
        }
        return MonomialOrder::weighted(weights);
    }
    if (o.starts_with("M(")) {
        const auto entries = r.integers(argument(1), "a matrix entry");
        if (entries.size() != n * n) {
            r.fail(s.begin, std::to_string(n * n) + " matrix entries",
                   std::to_string(entries.size()));
        }
        std::vector<std::vector<std::int64_t>> rows(n);
        for (std::size_t i = 0; i < n; ++i) {
            rows[i].assign(entries.begin() + static_cast<long>(i * n),
                           entries.begin() + static_cast<long>((i + 1) * n));
        }
        return MonomialOrder::matrix(std::move(rows));
    }
    if (o.starts_with("(") && o.ends_with(")")) {
        std::vector<std::size_t> blocks;
        for (const Span block : r.split_commas({s.begin + 1, s.end - 1})) {
            const std::string_view b = r.view(block);
            if (b == "c" || b == "C") {
                continue;
            }
            if (b == "dp" && blocks.empty()) {
                return MonomialOrder::grevlex(n);  // (dp, C)
            }
            if (!b.starts_with("dp(") || !b.ends_with(")")) {
                r.fail(block.begin, "a block dp(k) (locus reads blocks of dp as elimination)",
                       r.found_at(block.begin));
            }
            const std::int64_t k = r.integer({block.begin + 3, block.end - 1}, "a block size");
            if (k < 1) {
                r.fail(block.begin + 3, "a positive block size", r.found_at(block.begin + 3));
            }
            blocks.push_back(static_cast<std::size_t>(k));
        }
        std::size_t total = 0;
        for (const std::size_t k : blocks) {
            total += k;
        }
        if (blocks.empty() || blocks.size() > 2 || total != n) {
            r.fail(s.begin, "one or two dp blocks covering the " + std::to_string(n) + " variables",
                   r.found_at(s.begin));
        }
        if (blocks.size() == 1) {
            return MonomialOrder::grevlex(n);
        }
        std::vector<std::size_t> eliminated(blocks[0]);
        for (std::size_t i = 0; i < blocks[0]; ++i) {
            eliminated[i] = i;
        }
        return MonomialOrder::elimination(n, std::move(eliminated));
    }
    r.fail(s.begin, "a global order: lp, dp, Dp, wp(..), M(..) or (dp(k),dp(m))",
           r.found_at(s.begin));
}

}  // namespace

IdealFile parse_singular_input(std::string_view original) {
    const std::string text = without_comments(original, true);
    const Reader r(text);
    IdealFile file;
    std::size_t start = 0;
    bool have_ideal = false;
    while (start < text.size() && !have_ideal) {
        const std::size_t semicolon = std::min(text.find(';', start), text.size());
        const Span statement = trimmed(text, {start, semicolon});
        start = semicolon + 1;
        if (r.word_at(statement.begin, "ring")) {
            // ring NAME = CHARACTERISTIC, (VARIABLES), ORDER
            const std::size_t equals = text.find('=', statement.begin);
            if (equals == std::string::npos || equals >= statement.end) {
                r.fail(statement.begin + 4, "'NAME = characteristic, (variables), order'",
                       r.found_at(r.skip_space(statement.begin + 4)));
            }
            const auto parts = r.split_commas({equals + 1, statement.end});
            if (parts.size() != 3) {
                r.fail(equals + 1, "characteristic, (variables), order (three parts)",
                       std::to_string(parts.size()) + " parts");
            }
            const std::string_view field = r.view(parts[0]);
            file.characteristic = field == "QQ" ? 0 : r.characteristic(parts[0]);
            if (r.at(parts[1].begin) != '(' || r.at(parts[1].end - 1) != ')') {
                r.fail(parts[1].begin, "the variables in parentheses", r.found_at(parts[1].begin));
            }
            std::vector<std::string> names = r.names({parts[1].begin + 1, parts[1].end - 1});
            MonomialOrder order = singular_order(r, parts[2], names.size());
            file.ring = PolyRing::make(std::move(names), std::move(order));
        } else if (r.word_at(statement.begin, "qring")) {
            r.fail(statement.begin, "a polynomial ring (quotient rings are not read)", "'qring'");
        } else if (r.word_at(statement.begin, "ideal")) {
            if (!file.ring) {
                r.fail(statement.begin, "a 'ring' statement before the ideal", "'ideal'");
            }
            const std::size_t equals = text.find('=', statement.begin);
            if (equals == std::string::npos || equals >= statement.end) {
                r.fail(statement.begin + 5, "'NAME = generators'",
                       r.found_at(r.skip_space(statement.begin + 5)));
            }
            r.generators(trimmed(text, {equals + 1, statement.end}), file);
            have_ideal = true;
        }
        // Other statements (option(...), LIB, std(I), ...) are not part of the ideal.
    }
    if (!file.ring) {
        r.fail(text.size(), "a 'ring r = 0, (x,y,z), dp;' statement", "end of input");
    }
    if (!have_ideal) {
        r.fail(text.size(), "an 'ideal I = ...;' statement", "end of input");
    }
    return file;
}

namespace {

// Macaulay2's MonomialOrder value for `n` variables.
MonomialOrder macaulay2_order(const Reader& r, Span s, std::size_t n) {
    const std::string_view o = r.view(s);
    if (o == "Lex") {
        return MonomialOrder::lex(n);
    }
    if (o == "GLex") {
        return MonomialOrder::grlex(n);
    }
    if (o == "GRevLex") {
        return MonomialOrder::grevlex(n);
    }
    if (o.starts_with("Eliminate")) {
        // Macaulay2's Eliminate k: the weights (1,…,1,0,…,0) of the first k variables, ties by
        // GRevLex on all of them; as a matrix: that row, then grevlex's rows.
        const std::int64_t k =
            r.integer({s.begin + 9, s.end}, "the number of variables to eliminate");
        if (k < 1 || static_cast<std::size_t>(k) >= n) {
            r.fail(s.begin + 9, "from 1 to " + std::to_string(n - 1) + " variables",
                   r.found_at(r.skip_space(s.begin + 9)));
        }
        // GRevLex's rows after the all-ones row are −e_v for v = n−1 … 1; the one for v = k is
        // then a combination of the rows before it (1 − w − e_{k+1} − … − e_{n−1} = e_k) and is
        // left out, which keeps the matrix square and of full rank.
        std::vector<std::vector<std::int64_t>> rows;
        rows.emplace_back(n, 0);
        std::fill(rows[0].begin(), rows[0].begin() + k, 1);
        rows.emplace_back(n, 1);
        for (std::size_t v = n - 1; v >= 1; --v) {
            if (v == static_cast<std::size_t>(k)) {
                continue;
            }
            rows.emplace_back(n, 0);
            rows.back()[v] = -1;
        }
        return MonomialOrder::matrix(std::move(rows));
    }
    if (o.starts_with("{") && o.ends_with("}")) {
        const auto items = r.split_commas({s.begin + 1, s.end - 1});
        std::vector<std::vector<std::int64_t>> weight_rows;
        std::vector<std::size_t> grevlex_blocks;
        for (const Span item : items) {
            const std::string_view text = r.view(item);
            const auto arrow = text.find("=>");
            if (arrow == std::string_view::npos) {
                r.fail(item.begin, "'Weights => {..}' or 'GRevLex => ..'", r.found_at(item.begin));
            }
            const Span key = trimmed(std::string_view(text), {0, arrow});
            const Span value_in_item = trimmed(text, {arrow + 2, text.size()});
            const Span value{item.begin + value_in_item.begin, item.begin + value_in_item.end};
            const std::string_view name = text.substr(key.begin, key.end - key.begin);
            const bool braced = r.at(value.begin) == '{' && r.at(value.end - 1) == '}';
            if (name == "Weights" && braced) {
                weight_rows.push_back(r.integers({value.begin + 1, value.end - 1}, "a weight"));
            } else if (name == "GRevLex" && braced && items.size() == 1) {
                const auto weights = r.integers({value.begin + 1, value.end - 1}, "a weight");
                if (weights.size() != n) {
                    r.fail(value.begin, "one weight per variable", r.found_at(value.begin));
                }
                return MonomialOrder::weighted(weights);
            } else if (name == "GRevLex" && !braced) {
                const std::int64_t k = r.integer(value, "a block size");
                if (k < 1) {
                    r.fail(value.begin, "a positive block size", r.found_at(value.begin));
                }
                grevlex_blocks.push_back(static_cast<std::size_t>(k));
            } else {
                r.fail(item.begin, "'Weights => {..}' or 'GRevLex => ..'", r.found_at(item.begin));
            }
        }
        if (!weight_rows.empty() && grevlex_blocks.empty()) {
            for (const auto& row : weight_rows) {
                if (row.size() != n) {
                    r.fail(s.begin, "weight rows of " + std::to_string(n) + " entries",
                           std::to_string(row.size()) + " entries");
                }
            }
            return MonomialOrder::matrix(std::move(weight_rows));
        }
        std::size_t total = 0;
        for (const std::size_t k : grevlex_blocks) {
            total += k;
        }
        if (weight_rows.empty() && !grevlex_blocks.empty() && grevlex_blocks.size() <= 2 &&
            total == n) {
            if (grevlex_blocks.size() == 1) {
                return MonomialOrder::grevlex(n);
            }
            std::vector<std::size_t> eliminated(grevlex_blocks[0]);
            for (std::size_t i = 0; i < eliminated.size(); ++i) {
                eliminated[i] = i;
            }
            return MonomialOrder::elimination(n, std::move(eliminated));
        }
    }
    r.fail(s.begin,
           "Lex, GLex, GRevLex, Eliminate k, {GRevLex => {weights}}, {GRevLex => k, GRevLex => m} "
           "or {Weights => {..}, ..}",
           r.found_at(s.begin));
}

}  // namespace

IdealFile parse_macaulay2_input(std::string_view original) {
    const std::string text = without_comments(original, false);
    const Reader r(text);
    IdealFile file;
    // The ring: QQ[...] or ZZ/p[...].
    std::size_t bracket = std::string::npos;
    for (std::size_t i = 0; i < text.size() && bracket == std::string::npos; ++i) {
        if (r.word_at(i, "QQ")) {
            const std::size_t j = r.skip_space(i + 2);
            if (r.at(j) == '[') {
                bracket = j;
                file.characteristic = 0;
            }
        } else if (r.word_at(i, "ZZ")) {
            std::size_t j = r.skip_space(i + 2);
            if (r.at(j) != '/') {
                continue;
            }
            const std::size_t digits = r.skip_space(j + 1);
            std::size_t end = digits;
            while (std::isdigit(static_cast<unsigned char>(r.at(end)))) {
                ++end;
            }
            j = r.skip_space(end);
            if (r.at(j) == '[') {
                file.characteristic = r.characteristic({digits, end});
                if (file.characteristic == 0) {
                    r.fail(digits, "a prime (ZZ/p)", r.found_at(digits));
                }
                bracket = j;
            }
        }
    }
    if (bracket == std::string::npos) {
        r.fail(text.size(), "a ring 'R = QQ[x,y,z]' (or ZZ/p[...])", "end of input");
    }
    const std::size_t ring_end = r.closing(bracket);
    if (r.at(r.skip_space(ring_end)) == '/') {
        r.fail(r.skip_space(ring_end), "a polynomial ring (quotient rings are not read)", "'/'");
    }
    std::vector<std::string> names;
    std::optional<Span> order_value;
    for (const Span item : r.split_commas({bracket + 1, ring_end - 1})) {
        const std::string_view t = r.view(item);
        const auto arrow = t.find("=>");
        if (arrow == std::string_view::npos) {
            for (std::string& name : r.names(item)) {
                names.push_back(std::move(name));
            }
            continue;
        }
        const Span key = trimmed(text, {item.begin, item.begin + arrow});
        if (r.view(key) != "MonomialOrder") {
            r.fail(item.begin, "variables or 'MonomialOrder => ...'", r.found_at(item.begin));
        }
        order_value = trimmed(text, {item.begin + arrow + 2, item.end});
    }
    if (names.empty()) {
        r.fail(bracket + 1, "the variables", r.found_at(bracket + 1));
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (std::find(names.begin(), names.begin() + static_cast<long>(i), names[i]) !=
            names.begin() + static_cast<long>(i)) {
            r.fail(bracket + 1, "a name not declared before", "'" + names[i] + "' a second time");
        }
    }
    MonomialOrder order = order_value ? macaulay2_order(r, *order_value, names.size())
                                      : MonomialOrder::grevlex(names.size());
    file.ring = PolyRing::make(std::move(names), std::move(order));
    // The first ideal(...) or ideal{...} after the ring.
    for (std::size_t i = ring_end; i < text.size(); ++i) {
        if (!r.word_at(i, "ideal")) {
            continue;
        }
        const std::size_t open = r.skip_space(i + 5);
        if (r.at(open) != '(' && r.at(open) != '{') {
            r.fail(open, "'(' or '{' and the generators", r.found_at(open));
        }
        const std::size_t close = r.closing(open);
        Span list = trimmed(text, {open + 1, close - 1});
        // ideal(0_R), as locus prints the zero ideal.
        if (r.view(list).starts_with("0_")) {
            return file;
        }
        r.generators(list, file);
        return file;
    }
    r.fail(text.size(), "an ideal 'I = ideal(...)' after the ring", "end of input");
}

IdealFormat detect_ideal_format(std::string_view text) {
    const std::string singular = without_comments(text, true);
    const Reader r(singular);
    for (std::size_t i = r.skip_space(0); i < singular.size();) {
        if (r.word_at(i, "vars")) {
            return IdealFormat::ideal_file;
        }
        if (r.word_at(i, "ring")) {
            return IdealFormat::singular;
        }
        // The next statement's start (Singular) or line (an ideal file).
        const std::size_t next = singular.find_first_of(";\n", i);
        if (next == std::string::npos) {
            break;
        }
        i = r.skip_space(next + 1);
    }
    const std::string m2 = without_comments(text, false);
    const Reader q(m2);
    for (std::size_t i = 0; i < m2.size(); ++i) {
        if (q.word_at(i, "QQ") || q.word_at(i, "ZZ")) {
            std::size_t j = q.skip_space(i + 2);
            if (q.at(j) == '/') {
                j = q.skip_space(j + 1);
                while (std::isdigit(static_cast<unsigned char>(q.at(j)))) {
                    ++j;
                }
                j = q.skip_space(j);
            }
            if (q.at(j) == '[') {
                return IdealFormat::macaulay2;
            }
        }
    }
    if (looks_like_msolve(text)) {
        return IdealFormat::msolve;
    }
    return IdealFormat::ideal_file;
}

IdealFile parse_ideal_text(std::string_view text, IdealFormat format) {
    switch (format) {
    case IdealFormat::msolve:
        return parse_msolve_file(text);
    case IdealFormat::singular:
        return parse_singular_input(text);
    case IdealFormat::macaulay2:
        return parse_macaulay2_input(text);
    case IdealFormat::ideal_file:
        break;
    }
    return parse_ideal_file(text);
}

}  // namespace locus::algebra
