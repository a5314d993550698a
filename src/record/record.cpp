#include "record/record.hpp"

#include <string>
#include <utility>

namespace skipnc::record {

void add_warning(std::vector<Warning>& list, Warning w) {
  for (Warning& have : list) {
    if (have.line == w.line && have.context == w.context && have.code == w.code) {
      ++have.count;
      return;
    }
  }
  if (list.size() == kMaxWarnings) {
    list.push_back(Warning{"warnings_dropped", w.context, w.line,
                           "more than " + std::to_string(kMaxWarnings) +
                               " places raised warnings; later ones are not listed"});
  }
  if (list.size() > kMaxWarnings) return;
  list.push_back(std::move(w));
}

}  // namespace skipnc::record
