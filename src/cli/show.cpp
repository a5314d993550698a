#include "cli/show.hpp"

#include <iostream>
#include <string_view>

#include "config/machine_config.hpp"
#include "core/embedded.hpp"

namespace skipnc::cli {
namespace {

// What `show` can print: a built-in file's place in data/ for each topic.
struct Topic {
  std::string_view what;
  std::string_view help;
};
constexpr Topic kTopics[] = {
    {"machine",
     "skipnc show machine NAME: a built-in machine file (extend it with extends = \"NAME\")"},
    {"machines", "skipnc show machines: the names of the built-in machines"},
    {"demo", "skipnc show demo: the demo's program and scene"},
};

int usage(std::string_view why) {
  std::cerr << "skipnc show: " << why << "\n";
  for (const auto& t : kTopics) std::cerr << "  " << t.help << "\n";
  return 2;
}

std::string known_machines() {
  std::string known;
  for (const auto& n : config::builtin_machine_names()) known += (known.empty() ? "" : ", ") + n;
  return known;
}

}  // namespace

int show_command(const ShowArgs& a) {
  if (a.what == "machines") {
    for (const auto& n : config::builtin_machine_names()) std::cout << n << "\n";
    return 0;
  }
  if (a.what == "machine") {
    if (a.name.empty()) return usage("which machine? (built-in: " + known_machines() + ")");
    const EmbeddedFile* f = embedded_entry("machines/" + a.name + ".toml");
    if (f == nullptr) {
      return usage("no built-in machine '" + a.name + "' (built-in: " + known_machines() + ")");
    }
    std::cout << f->content;
    return 0;
  }
  if (a.what == "demo") {
    if (!a.name.empty()) return usage("'show demo' takes no name");
    const EmbeddedFile* prog = embedded_entry("demo/probe_demo.nc");
    const EmbeddedFile* scene = embedded_entry("demo/probe_demo.toml");
    if (prog == nullptr || scene == nullptr) return usage("the demo's files are not in this build");
    std::cout << "# probe_demo.nc: skipnc run probe_demo.nc -m mill3 -s probe_demo.toml\n"
              << prog->content << "\n# probe_demo.toml\n"
              << scene->content;
    return 0;
  }
  return usage(a.what.empty() ? "what should be shown?" : "unknown topic '" + a.what + "'");
}

}  // namespace skipnc::cli
