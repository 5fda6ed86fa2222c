// Every accepted parametrization file of the repository (tests/data/, bench/data/implicit/),
// implicitized, checked at random rational parameter values by a checker that shares no code
// with locus' verification: the test reads the .param text with its own evaluator over exact
// rationals (sin and cos of integer combinations of angles at rational points of the unit
// circle), parses the printed implicit equation with FLINT's own parser, and evaluates it there.
#include <flint/fmpq_mpoly.h>
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "algebra/print.h"
#include "implicit/implicitize.h"
#include "tests/support/test_data.h"

namespace locus::implicit {
namespace {

// An exact rational with RAII.
struct Q {
    fmpq_t v;
    Q() { fmpq_init(v); }
    explicit Q(long n, long d = 1) {
        fmpq_init(v);
        fmpq_set_si(v, n, static_cast<ulong>(d));
    }
    Q(const Q& o) {
        fmpq_init(v);
        fmpq_set(v, o.v);
    }
    Q& operator=(const Q& o) {
        fmpq_set(v, o.v);
        return *this;
    }
    ~Q() { fmpq_clear(v); }
    friend Q operator+(const Q& a, const Q& b) {
        Q r;
        fmpq_add(r.v, a.v, b.v);
        return r;
    }
    friend Q operator-(const Q& a, const Q& b) {
        Q r;
        fmpq_sub(r.v, a.v, b.v);
        return r;
    }
    friend Q operator*(const Q& a, const Q& b) {
        Q r;
        fmpq_mul(r.v, a.v, b.v);
        return r;
    }
};

// The point at which the map is evaluated: each parameter a rational, each angle a rational
// point (cos, sin) of the unit circle.
struct Point {
    std::map<std::string, Q> value;
    std::map<std::string, std::pair<Q, Q>> circle;
};

// A recursive-descent evaluator of the .param right-hand sides; throws on a zero divisor.
class Evaluator {
  public:
    Evaluator(const std::string& text, const Point& point) : s_(text), point_(point) {}
    Q run() {
        Q v = sum();
        skip();
        if (i_ != s_.size()) {
            throw std::runtime_error("trailing input in " + s_);
        }
        return v;
    }

  private:
    void skip() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) {
            ++i_;
        }
    }
    bool eat(char c) {
        skip();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    Q sum() {
        Q v = product();
        for (;;) {
            if (eat('+')) {
                v = v + product();
            } else if (eat('-')) {
                v = v - product();
            } else {
                return v;
            }
        }
    }
    Q product() {
        Q v = unary();
        for (;;) {
            if (eat('*')) {
                v = v * unary();
            } else if (eat('/')) {
                const Q d = unary();
                if (fmpq_is_zero(d.v)) {
                    throw std::domain_error("zero divisor");
                }
                fmpq_div(v.v, v.v, d.v);
            } else {
                return v;
            }
        }
    }
    Q unary() {
        if (eat('-')) {
            return Q(0) - unary();
        }
        if (eat('+')) {
            return unary();
        }
        Q base = atom();
        if (eat('^')) {
            skip();
            const std::size_t start = i_;
            while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) {
                ++i_;
            }
            Q r(1);
            for (long k = std::stol(s_.substr(start, i_ - start)); k > 0; --k) {
                r = r * base;
            }
            return r;
        }
        return base;
    }
    std::string name() {
        skip();
        const std::size_t start = i_;
        while (i_ < s_.size() &&
               (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) {
            ++i_;
        }
        return s_.substr(start, i_ - start);
    }
    Q atom() {
        skip();
        if (eat('(')) {
            Q v = sum();
            eat(')');
            return v;
        }
        if (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.') {
            const std::size_t start = i_;
            while (i_ < s_.size() &&
                   (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) {
                ++i_;
            }
            std::string digits = s_.substr(start, i_ - start);
            const auto dot = digits.find('.');
            long denominator = 1;
            if (dot != std::string::npos) {
                for (std::size_t k = dot + 1; k < digits.size(); ++k) {
                    denominator *= 10;
                }
                digits.erase(dot, 1);
            }
            Q r;
            fmpz_set_str(fmpq_numref(r.v), digits.c_str(), 10);
            fmpz_set_si(fmpq_denref(r.v), denominator);
            fmpq_canonicalise(r.v);
            return r;
        }
        const std::string id = name();
        if (id == "sin" || id == "cos") {
            // e^{iθ} for θ = Σ k·u at the angles' circle points.
            eat('(');
            Q re(1), im(0);
            bool first = true;
            while (first || eat('+') || (s_[i_] == '-')) {
                long sign = 1;
                if (eat('-')) {
                    sign = -1;
                }
                first = false;
                skip();
                long k = 1;
                if (std::isdigit(static_cast<unsigned char>(s_[i_]))) {
                    k = std::stol(name());
                    eat('*');
                }
                const std::string angle = name();
                if (eat('*')) {
                    k *= std::stol(name());
                }
                const auto& [c, sn] = point_.circle.at(angle);
                for (long j = 0; j < k; ++j) {
                    const Q s_signed = sign > 0 ? sn : Q(0) - sn;
                    const Q next_re = re * c - im * s_signed;
                    im = re * s_signed + im * c;
                    re = next_re;
                }
                skip();
                if (s_[i_] == ')') {
                    break;
                }
            }
            eat(')');
            return id == "cos" ? re : im;
        }
        return point_.value.at(id);
    }

    std::string s_;
    std::size_t i_ = 0;
    const Point& point_;
};

struct ParamFile {
    std::string path;
    std::vector<std::string> params;
    std::map<std::string, std::string> coordinates;  // x, y, z -> right-hand side
};

ParamFile read_param(const std::string& path) {
    ParamFile file{path, {}, {}};
    std::istringstream in(test::read_text(path));
    std::string line;
    while (std::getline(in, line)) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) {
            line.erase(hash);
        }
        const auto colon = line.find(':');
        const auto equals = line.find('=');
        if (colon != std::string::npos && line.find("params") != std::string::npos) {
            std::stringstream names(line.substr(colon + 1));
            std::string n;
            while (std::getline(names, n, ',')) {
                n.erase(0, n.find_first_not_of(" \t"));
                n.erase(n.find_last_not_of(" \t\r") + 1);
                file.params.push_back(n);
            }
        } else if (equals != std::string::npos) {
            std::string coordinate = line.substr(0, equals);
            coordinate.erase(0, coordinate.find_first_not_of(" \t"));
            coordinate.erase(coordinate.find_last_not_of(" \t") + 1);
            file.coordinates[coordinate] = line.substr(equals + 1);
        }
    }
    return file;
}

std::vector<std::string> param_files() {
    std::vector<std::string> files;
    for (const char* dir : {"/tests/data", "/tests/data/param", "/bench/data/implicit"}) {
        for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() + dir)) {
            const std::string path = entry.path().string();
            // The bicubic patch takes a minute to implicitize: a benchmark, not a test.
            if (entry.path().extension() == ".param" &&
                path.find("bezier_bicubic") == std::string::npos) {
                files.push_back(path);
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(ParamFiles, ImplicitEquationsVanishAtRandomRationalPoints) {
    const std::vector<std::string> files = param_files();
    ASSERT_GE(files.size(), 14u);
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<long> numerator(-40, 40), denominator(1, 17);
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        const ParamFile file = read_param(path);
        const Parametrization map = parse_parametrization(test::read_text(path));
        const ImplicitResult r = implicitize_auto(map);
        std::vector<algebra::Polynomial> equations = r.generators;
        if (r.equation) {
            equations = {*r.equation};
        }
        ASSERT_FALSE(equations.empty());
        // The equations through FLINT's parser, in x, y, z.
        fmpq_mpoly_ctx_t ctx;
        fmpq_mpoly_ctx_init(ctx, 3, ORD_LEX);
        const char* names[] = {"x", "y", "z"};
        std::vector<fmpq_mpoly_struct> parsed(equations.size());
        for (std::size_t e = 0; e < equations.size(); ++e) {
            fmpq_mpoly_init(&parsed[e], ctx);
            ASSERT_EQ(fmpq_mpoly_set_str_pretty(
                          &parsed[e], algebra::to_string(equations[e]).c_str(), names, ctx),
                      0);
        }
        int checked = 0;
        for (int attempt = 0; attempt < 40 && checked < 6; ++attempt) {
            Point point;
            for (const std::string& p : file.params) {
                point.value[p] = Q(numerator(rng), denominator(rng));
                // A rational point of the circle: ((1 − m²)/(1 + m²), 2m/(1 + m²)).
                const Q m(numerator(rng), denominator(rng));
                Q one_plus = Q(1) + m * m, c = Q(1) - m * m, s = Q(2) * m;
                fmpq_div(c.v, c.v, one_plus.v);
                fmpq_div(s.v, s.v, one_plus.v);
                point.circle[p] = {c, s};
            }
            std::vector<Q> xyz(3, Q(0));
            try {
                for (int i = 0; i < 3; ++i) {
                    const auto it = file.coordinates.find(names[i]);
                    if (it != file.coordinates.end()) {
                        xyz[static_cast<std::size_t>(i)] = Evaluator(it->second, point).run();
                    }
                }
            } catch (const std::domain_error&) {
                continue;  // a pole of the map
            }
            fmpq* values[] = {xyz[0].v, xyz[1].v, xyz[2].v};
            for (auto& equation : parsed) {
                Q result;
                fmpq_mpoly_evaluate_all_fmpq(result.v, &equation, values, ctx);
                EXPECT_TRUE(fmpq_is_zero(result.v));
            }
            ++checked;
        }
        EXPECT_GE(checked, 6);
        for (auto& equation : parsed) {
            fmpq_mpoly_clear(&equation, ctx);
        }
        fmpq_mpoly_ctx_clear(ctx);
    }
}

}  // namespace
}  // namespace locus::implicit
