// The page's script (plot_*.js, joined) and styles (src/plot/assets/), compiled in by
// src/plot/embed_assets.cmake so that the page needs no network.
#pragma once

#include <string_view>

namespace skipnc::plot::assets {

std::string_view plot_js() noexcept;
std::string_view plot_css() noexcept;

}  // namespace skipnc::plot::assets
