#pragma once
// The page (serve/page.html: HTML, CSS and JavaScript in one file, no external resources),
// compiled into the binary by CMake (serve/page_asset.cpp.in).
#include <string_view>

namespace raycast::serve {

std::string_view page_html();

}  // namespace raycast::serve
