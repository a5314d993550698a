#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "config/machine_config.hpp"

namespace skipnc::config {

Parameters::Parameters(const Dialect* dialect) : dialect_(dialect) {
  if (dialect_ == nullptr) return;
  table_.reserve(dialect_->params.size());
  for (const ParamDef& p : dialect_->params) {
    // The first definition of a number counts (as Dialect::param finds it).
    if (dialect_->param(p.number) == &p) table_.emplace_back(p.number, p.default_value);
  }
  std::sort(table_.begin(), table_.end());
}

double Parameters::get(int number) const noexcept {
  const auto it =
      std::lower_bound(table_.begin(), table_.end(), number,
                       [](const std::pair<int, double>& e, int n) { return e.first < n; });
  return it != table_.end() && it->first == number ? it->second : 0.0;
}

void Parameters::set(int number, double value) {
  values_[number] = value;
  const auto it =
      std::lower_bound(table_.begin(), table_.end(), number,
                       [](const std::pair<int, double>& e, int n) { return e.first < n; });
  if (it != table_.end() && it->first == number) {
    it->second = value;
  } else {
    table_.insert(it, {number, value});
  }
}

bool Parameters::bit(int number, int b) const noexcept {
  const auto v = static_cast<long long>(get(number));
  return ((v >> b) & 1LL) != 0;
}

Result<void> Parameters::apply(const ParamSetting& s) {
  const ParamDef* d = dialect_ != nullptr ? dialect_->param(s.number) : nullptr;
  const std::string name =
      std::to_string(s.number) + (s.bit >= 0 ? "#" + std::to_string(s.bit) : "");
  if (d == nullptr) {
    return fail(AlarmId::kConfig,
                "parameter " + name + " is not a parameter of dialect '" +
                    (dialect_ ? dialect_->name : std::string("?")) + "'",
                s.loc);
  }
  if (s.bit >= 0) {
    if (d->kind != ParamKind::kBits) {
      return fail(
          AlarmId::kConfig,
          "parameter " + std::to_string(s.number) + " (" + d->name + ") is not a bit parameter",
          s.loc);
    }
    if (s.bit > 7 || (s.value != 0.0 && s.value != 1.0)) {
      return fail(AlarmId::kConfig, "parameter " + name + " takes 0 or 1", s.loc);
    }
    const auto cur = static_cast<long long>(get(s.number));
    const long long mask = 1LL << s.bit;
    set(s.number, static_cast<double>(s.value != 0.0 ? (cur | mask) : (cur & ~mask)));
    return {};
  }
  if (!(s.value >= d->min && s.value <= d->max) ||
      (d->kind != ParamKind::kReal && s.value != std::floor(s.value))) {
    return fail(
        AlarmId::kConfig,
        "parameter " + name + " (" + d->name + ") = " + std::to_string(s.value) +
            " is out of range: " + (d->kind == ParamKind::kReal ? "a number" : "a whole number") +
            " from " + std::to_string(d->min) + " to " + std::to_string(d->max),
        s.loc);
  }
  set(s.number, s.value);
  return {};
}

Result<ParamSetting> Parameters::parse_setting(std::string_view text) {
  ParamSetting s;
  const auto eq = text.find('=');
  auto bad = [&] {
    return fail(AlarmId::kUsage, "parameter setting '" + std::string(text) +
                                     "' must be N=VALUE or N#BIT=0|1 (e.g. 6200#7=1)");
  };
  if (eq == std::string_view::npos) return bad();
  const std::string_view lhs = text.substr(0, eq);
  const std::string_view rhs = text.substr(eq + 1);
  const auto hash = lhs.find('#');
  const std::string_view num = lhs.substr(0, hash);
  auto r = std::from_chars(num.data(), num.data() + num.size(), s.number);
  if (r.ec != std::errc{} || r.ptr != num.data() + num.size() || s.number <= 0) return bad();
  if (hash != std::string_view::npos) {
    const std::string_view b = lhs.substr(hash + 1);
    auto rb = std::from_chars(b.data(), b.data() + b.size(), s.bit);
    if (rb.ec != std::errc{} || rb.ptr != b.data() + b.size() || s.bit < 0 || s.bit > 7) {
      return bad();
    }
  }
  auto rv = std::from_chars(rhs.data(), rhs.data() + rhs.size(), s.value);
  if (rv.ec != std::errc{} || rv.ptr != rhs.data() + rhs.size() || !std::isfinite(s.value)) {
    return bad();
  }
  return s;
}

}  // namespace skipnc::config
