// What every command needs before it runs: machine, dialect, parameters and
// scene, loaded and checked, with errors that name file, line and column.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/scene.hpp"

namespace skipnc::run {

struct SessionOptions {
  std::string machine = "mill3";  // file or built-in name
  std::string dialect;            // empty: the machine's
  std::string scene;              // empty: no scene
  std::vector<std::string> params;
};

// A machine or scene given as TOML text (the Python module's dicts): read
// instead of a file, SessionOptions' `machine` / `scene` naming it in errors;
// relative paths in it (`extends`, a mesh's file) are taken from that name's
// folder. Empty: the file (or built-in machine) as usual.
struct SessionTexts {
  std::string machine;
  std::string scene;
};

struct Session {
  // The files as given: an error's location points into these, so they
  // live as long as the session (not as long as the options).
  std::string machine_file;
  std::string scene_file;
  SessionTexts texts;  // the texts read instead of files, when given
  config::MachineConfig machine;
  config::Dialect dialect;
  std::unique_ptr<config::Parameters> params;
  machine::Scene scene;
};

// The machine is loaded first so that a dialect error can still be reported
// with the dialect's numbers where possible. `partial` receives whatever was
// loaded before an error.
[[nodiscard]] Result<void> open_session(const SessionOptions& o, Session& s);
[[nodiscard]] Result<void> open_session(const SessionOptions& o, const SessionTexts& texts,
                                        Session& s);

// The warnings that stay warnings under --strict: those the command line
// names (--allow) and the scene's [strict] allow, each once.
std::vector<std::string> allowed_warnings(const Session& s, const std::vector<std::string>& cli);
// kUsage naming the codes when one of --allow is no warning's code.
[[nodiscard]] Result<void> check_allow(const std::vector<std::string>& cli);

// "#5061", "5061", "#<NC.SysVars.G31.LCS.X>" -> number or name.
struct VarRef {
  std::string key;  // as reported (without '#')
  int number = -1;
  std::string name;  // for #<name>
};
[[nodiscard]] Result<VarRef> parse_var_ref(const std::string& text);

// "file:line:column: CODE message" for standard error.
std::string describe(const Error& e, const config::Dialect* d);

}  // namespace skipnc::run
