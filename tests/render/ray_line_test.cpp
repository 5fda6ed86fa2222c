// The `locus trace` ray-line reader: what it accepts, and where it says a line goes wrong.
#include "render/ray_line.h"

#include <gtest/gtest.h>

#include <string>

#include "algebra/error.h"

namespace locus::render {
namespace {

TEST(RayLine, ReadsSixNumbersWithBlanksAroundThem) {
    const auto ray = parse_ray_line("\t0 0.5  -2e-3 1 0 -1 \r", 1);
    ASSERT_TRUE(ray.has_value());
    EXPECT_EQ(ray->origin, Vec3(0, 0.5, -2e-3));
    EXPECT_EQ(ray->direction, Vec3(1, 0, -1));
}

TEST(RayLine, BlankLinesCarryNoRay) {
    EXPECT_FALSE(parse_ray_line("", 3).has_value());
    EXPECT_FALSE(parse_ray_line("  \t\r", 3).has_value());
}

// Each bad line with the column and the text its message must name.
struct BadLine {
    std::string text;
    std::size_t column;
    std::string found;
};

TEST(RayLine, BadLinesNameTheColumnAndWhatIsThere) {
    const BadLine cases[] = {
        {"0 0 5 x 0 -1", 7, "'x'"},
        {"0 0 5 0 0", 10, "the end of the line"},
        {"0 0 5 0 0 -1 7", 14, "'7'"},
        {"0 0 5 nan 0 -1", 7, "'nan'"},
        {"0 0 5 inf 0 -1", 7, "'inf'"},
        {"0 0 5 1e999 0 -1", 7, "'1e999'"},
        {"0 0 5 0 0 -1x", 13, "'x'"},
        {"0,0,5,0,0,-1", 2, "','"},
        {std::string("0 0 5 0 0 \0", 11), 11, "U+0000 (a control character)"},
        {"0 0 5 0 0 0", 1, "0 0 0"},
    };
    for (const BadLine& bad : cases) {
        try {
            parse_ray_line(bad.text, 4);
            ADD_FAILURE() << "accepted: " << bad.text;
        } catch (const ParseError& e) {
            EXPECT_EQ(e.line(), 4u) << bad.text;
            EXPECT_EQ(e.column(), bad.column) << bad.text;
            EXPECT_EQ(e.found(), bad.found) << bad.text;
        }
    }
}

}  // namespace
}  // namespace locus::render
