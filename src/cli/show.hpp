// `skipnc show`: prints the built-in files (machines, the demo's program and
// scene) so that they can be copied and changed.
#pragma once

#include <string>

namespace skipnc::cli {

struct ShowArgs {
  std::string what;  // "machine", "machines", "demo"
  std::string name;  // the machine's name for "machine"
};

int show_command(const ShowArgs& a);

}  // namespace skipnc::cli
