#include "render/ray_line.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "algebra/error.h"

namespace locus::render {
namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// What stands at `at`, for the message: a word of letters, digits and number signs, else the
// one character, or the end of the line.
std::string word_at(std::string_view text, std::size_t at) {
    if (at >= text.size()) {
        return "the end of the line";
    }
    const auto first = static_cast<unsigned char>(text[at]);
    if (first < 0x20 || first == 0x7F) {
        char code[32];
        std::snprintf(code, sizeof code, "U+%04X (a control character)", first);
        return code;
    }
    const auto in_word = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-';
    };
    std::size_t end = at + 1;
    if (in_word(text[at])) {
        while (end < text.size() && in_word(text[end]) && end - at < 24) {
            ++end;
        }
    }
    std::string word = "'";
    word.append(text.substr(at, end - at));
    word.push_back('\'');
    return word;
}

}  // namespace

std::optional<Ray> parse_ray_line(std::string_view text, std::size_t line) {
    // strtod needs a terminated string; a copy also stops it at an embedded NUL.
    const std::string copy(text);
    const char* const begin = copy.c_str();
    const char* cursor = begin;
    const auto skip_blanks = [&] {
        while (is_blank(*cursor)) {
            ++cursor;
        }
    };
    skip_blanks();
    if (*cursor == '\0' && static_cast<std::size_t>(cursor - begin) == copy.size()) {
        return std::nullopt;
    }
    std::array<double, 6> values{};
    for (double& value : values) {
        skip_blanks();
        const std::size_t column = static_cast<std::size_t>(cursor - begin);
        char* end = nullptr;
        value = std::strtod(cursor, &end);
        if (end == cursor || !std::isfinite(value)) {
            throw ParseError(line, column + 1, "a finite decimal number (ray: ox oy oz dx dy dz)",
                             word_at(text, column));
        }
        cursor = end;
        if (!is_blank(*cursor) && *cursor != '\0') {
            const std::size_t at = static_cast<std::size_t>(cursor - begin);
            throw ParseError(line, at + 1, "a space after the number", word_at(text, at));
        }
    }
    skip_blanks();
    const std::size_t rest = static_cast<std::size_t>(cursor - begin);
    if (rest != copy.size()) {
        throw ParseError(line, rest + 1, "the end of the line after six numbers",
                         word_at(text, rest));
    }
    const Ray ray{{values[0], values[1], values[2]}, {values[3], values[4], values[5]}};
    if (ray.direction == Vec3(0.0)) {
        throw ParseError(line, 1, "a non-zero direction (dx dy dz)", "0 0 0");
    }
    return ray;
}

}  // namespace locus::render
