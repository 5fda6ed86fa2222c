// GoogleTest names for tests parameterized by a trace method: "sphere_gradient", not
// "4-byte object <05-00 00-00>".
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "render/trace_method.h"

namespace locus::test {

inline std::string trace_method_name(const ::testing::TestParamInfo<render::TraceMethod>& info) {
    std::string name(render::to_string(info.param));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

}  // namespace locus::test
