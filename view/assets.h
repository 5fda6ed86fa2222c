// The page of `locus view` (view/assets/), compiled into the binary by embed_assets.cmake.
#pragma once

#include <string_view>

namespace locus::view::assets {

extern const std::string_view index_html;
extern const std::string_view app_js;
extern const std::string_view style_css;

}  // namespace locus::view::assets
