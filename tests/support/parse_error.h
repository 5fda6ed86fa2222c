// Asserting parse errors: position and wording, not just "throws" (STYLE.md P13).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "algebra/error.h"

namespace locus::test {

struct BadInput {
    const char* text;
    std::size_t line, column;
    const char* expected_fragment;  // part of ParseError::expected()
};

// Runs `parse` and checks that it throws a ParseError at the case's position and wording.
template <class Parse>
void expect_parse_error(const BadInput& c, Parse parse) {
    SCOPED_TRACE(std::string("input: ") + c.text);
    try {
        parse();
        ADD_FAILURE() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), c.line);
        EXPECT_EQ(e.column(), c.column);
        EXPECT_NE(e.expected().find(c.expected_fragment), std::string::npos) << e.what();
    }
}

}  // namespace locus::test
