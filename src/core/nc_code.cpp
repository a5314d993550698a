#include "core/nc_code.hpp"

namespace skipnc {

std::string code_name(GCode g, CodeStyle style) {
  std::string s = "G";
  if (style == CodeStyle::kManual && g.number() < 10) s += '0';
  s += std::to_string(g.number());
  if (g.decimal() != 0) s += "." + std::to_string(g.decimal());
  return s;
}

std::string m_code_name(int m) {
  return "M" + std::to_string(m);
}

}  // namespace skipnc
