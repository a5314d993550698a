// Reads an SVG the binary wrote with python3's ElementTree (an XML error
// fails the test) through a script that prints what a test checks as JSON.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_cli.hpp"

namespace skipnc::test {

inline nlohmann::json read_svg_with(const TempDir& dir, const char* script,
                                    const std::string& svg) {
  const auto file = dir.write("svg_reader.py", script);
  const auto out = dir.path / "svg.json";
  const std::string cmd = "python3 " + shell_quote(file.string()) + " " + shell_quote(svg) + " > " +
                          shell_quote(out.string());
  EXPECT_EQ(std::system(cmd.c_str()), 0) << "the SVG is not well-formed XML";
  return nlohmann::json::parse(read_file(out), nullptr, false);
}

}  // namespace skipnc::test
