// The skip family as the user sees it in the CSV trace of `skipnc run`:
// following error and torque columns (rule 43) and CompassNC's PLC handshake
// columns (rule 32).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

namespace skipnc::rules {
namespace {

using test::read_file;
using test::run_cli;
using test::TempDir;

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int col(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return static_cast<int>(i);
    }
    return -1;
  }
};

Csv parse_csv(const std::string& text) {
  Csv c;
  std::istringstream in(text);
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string cell;
    std::vector<double> row;
    // Every column is a number but `file` (the block's file name): NaN here.
    for (std::size_t k = 0; std::getline(ls, cell, ','); ++k) {
      if (first)
        c.header.push_back(cell);
      else
        row.push_back(k < c.header.size() && c.header[k] == "file" ? std::nan("")
                                                                   : std::stod(cell));
    }
    if (!first) c.rows.push_back(std::move(row));
    first = false;
  }
  return c;
}

TEST(Rules, rule_43_the_trace_shows_following_error_and_torque_rising_to_the_skip) {
  TempDir tmp;
  const auto nc = tmp.write("t.nc", "G21 G90 G54 G31 P98 Z-10. F300. Q50\nM30\n");
  const auto scene =
      tmp.write("s.toml", "[[stop]]\naxis = \"Z\"\nat = -3.0\ndirection = \"decreasing\"\n");
  const auto trace = tmp.path / "trace.csv";
  const auto r =
      run_cli({"run", nc.string(), "-s", scene.string(), "--trace", trace.string(), "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const Csv c = parse_csv(read_file(trace));
  const int act = c.col("Z_act"), ferr = c.col("Z_ferr"), torque = c.col("Z_torque");
  ASSERT_GE(act, 0);
  ASSERT_GE(ferr, 0) << "following error column";
  ASSERT_GE(torque, 0);
  std::size_t contact = 0, skip = 0;
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    if (contact == 0 && c.rows[i][act] == -3.0) contact = i;
    if (contact != 0 && skip == 0 && std::fabs(c.rows[i][torque]) >= 50.0) skip = i;
  }
  ASSERT_GT(contact, 0U);
  ASSERT_GT(skip, contact);
  // 5 mm/s into the stop at 100 %/mm: the error grows 5 um and the torque
  // 0.5 % per period.
  for (std::size_t i = contact + 1; i <= skip; ++i) {
    EXPECT_NEAR(std::fabs(c.rows[i][ferr]) - std::fabs(c.rows[i - 1][ferr]), 0.005, 1e-6);
    EXPECT_NEAR(std::fabs(c.rows[i][torque]), 100.0 * std::fabs(c.rows[i][ferr]), 1e-6);
  }
  EXPECT_NEAR(std::fabs(c.rows[skip][torque]), 50.0, 1e-9) << "the skip at the limit";
  EXPECT_NEAR(c.rows.back()[ferr], 0.0, 1e-9) << "the block ends at the stop: no error left";
}

TEST(Rules, rule_32_compass_handshake_columns_in_the_trace) {
  TempDir tmp;
  const auto nc = tmp.write("t.nc", "G21 G90 G54 G31 X20. F600.\nG1 Y5.\nM30\n");
  const auto scene = tmp.write(
      "s.toml",
      "[[trigger]]\nsignal = \"SKIP\"\naxis = \"X\"\nat = 5.0\ndirection = \"increasing\"\n");
  const auto trace = tmp.path / "trace.csv";
  const auto r = run_cli(
      {"run", nc.string(), "-d", "compass", "-s", scene.string(), "--trace", trace.string(), "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const Csv c = parse_csv(read_file(trace));
  const int active = c.col("G31SkipMove.Active"), skip = c.col("G31SkipMove.Skip"),
            rec = c.col("G31SkipMove.PositionsRecorded"), done = c.col("G31SkipMove.Done"),
            line = c.col("line"), probe = c.col("X0.4");
  ASSERT_GE(active, 0);
  ASSERT_GE(skip, 0);
  ASSERT_GE(rec, 0);
  ASSERT_GE(done, 0);
  ASSERT_GE(probe, 0);
  auto first = [&](int col, double v) -> int {
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
      if (c.rows[i][col] == v) return static_cast<int>(i);
    }
    return -1;
  };
  const int a = first(active, 1), s = first(skip, 1), p = first(rec, 1), d = first(done, 1),
            n = first(line, 2), in = first(probe, 1);
  ASSERT_GE(a, 0);
  EXPECT_EQ(s, in) << "Skip is set in the period the input rises";
  EXPECT_LE(s, p);
  EXPECT_LT(a, s);
  EXPECT_GE(d, p);
  EXPECT_EQ(c.rows[static_cast<std::size_t>(d)][active], 0.0) << "Done resets Active";
  EXPECT_GT(n, d) << "the next block moves after Active is reset";
  // The fanuc dialect has no such handshake: no columns.
  const auto r2 =
      run_cli({"run", nc.string(), "-s", scene.string(), "--trace", trace.string(), "-q"});
  ASSERT_EQ(r2.exit_code, 0);
  EXPECT_LT(parse_csv(read_file(trace)).col("G31SkipMove.Active"), 0);
}

// The trace's numbers are rounded to 6 decimals (1 nm), trailing zeros
// dropped.
TEST(Trace, numbers_are_written_to_six_decimals) {
  TempDir tmp;
  const auto nc = tmp.write("t.nc", "G21 G90 G54 G1 X1.2345678 Z-0.5 F777.7\nM30\n");
  const auto trace = tmp.path / "trace.csv";
  const auto r = run_cli({"run", nc.string(), "--trace", trace.string(), "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const std::string text = read_file(trace);
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  std::size_t cells = 0, fractional = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string cell;
    for (int k = 0; std::getline(ls, cell, ','); ++k) {
      if (k == 2) continue;  // the `file` column: the program's name
      ++cells;
      ASSERT_EQ(cell.find_first_of("eE"), std::string::npos) << cell;
      const auto dot = cell.find('.');
      if (dot == std::string::npos) continue;
      ++fractional;
      ASSERT_LE(cell.size() - dot - 1, 6u) << cell;
      ASSERT_NE(cell.back(), '0') << cell;
    }
  }
  EXPECT_GT(cells, 1000u);
  EXPECT_GT(fractional, 100u);
  // The last row: the command at the end point, X1.2345678 to the nearest
  // nanometre.
  const Csv c = parse_csv(text);
  EXPECT_DOUBLE_EQ(c.rows.back()[static_cast<std::size_t>(c.col("X_cmd"))], 1.234568);
  EXPECT_DOUBLE_EQ(c.rows.back()[static_cast<std::size_t>(c.col("Z_cmd"))], -0.5);
}

// --trace-every N keeps the rows of the periods whose number is a multiple
// of N: every 100th row of the full trace of a 1.05 s dwell (1050 periods of
// 1 ms, exactly: the time inside a segment no longer drifts into an extra
// period), the same columns and values, and the run's last period (issue
// 31: the trace ends where the run ends); an N of 0 is refused before the run.
TEST(TraceCli, TraceEveryKeepsOneRowInN) {
  TempDir tmp;
  const auto nc = tmp.write("t.nc", "G21 G90 G54\nG04 X1.05\nM30\n");
  const auto all = tmp.path / "all.csv";
  const auto some = tmp.path / "some.csv";
  ASSERT_EQ(run_cli({"run", nc.string(), "--trace", all.string(), "-q"}).exit_code, 0);
  ASSERT_EQ(run_cli({"run", nc.string(), "--trace", some.string(), "--trace-every", "100", "-q"})
                .exit_code,
            0);
  const Csv a = parse_csv(read_file(all));
  const Csv c = parse_csv(read_file(some));
  ASSERT_EQ(a.rows.size(), 1050U);
  ASSERT_EQ(c.rows.size(), 11U);
  EXPECT_EQ(c.header, a.header);
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    const std::size_t period = i < 10 ? 100 * (i + 1) : 1050;
    EXPECT_NEAR(c.rows[i][0], 0.001 * static_cast<double>(period), 1e-9);
    const auto& full = a.rows[period - 1];
    ASSERT_EQ(c.rows[i].size(), full.size());
    for (std::size_t k = 0; k < full.size(); ++k) {
      if (!std::isnan(full[k])) {
        EXPECT_EQ(c.rows[i][k], full[k]) << "row " << i << " column " << k;
      }
    }
  }
  const auto bad = run_cli({"run", nc.string(), "--trace", some.string(), "--trace-every", "0"});
  EXPECT_NE(bad.exit_code, 0);
}

// With a touch probe in the scene the trace has probe_deflection (mm) and
// probe_contact: zero and 0 while the ball is free; in contact while the
// axis goes straight down, Z_act + deflection stays the height where the
// ball met the plate (the stylus takes up exactly the travel), and the ideal
// probe (no pre-travel) switches SKIP (X0.4) in the first contact period.
TEST(TraceCli, ProbeDeflectionAndContactColumns) {
  TempDir tmp;
  const std::string ex = std::string(SKIPNC_SOURCE_DIR) + "/examples/probing/";
  const auto trace = tmp.path / "t.csv";
  const auto r = run_cli({"run", ex + "surface.nc", "-s", ex + "fixture.scene.toml", "-m",
                          ex + "mill3_probe.machine.toml", "--trace", trace.string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const Csv c = parse_csv(read_file(trace));
  const int defl = c.col("probe_deflection"), contact = c.col("probe_contact"), z = c.col("Z_act"),
            skip = c.col("X0.4");
  ASSERT_GE(defl, 0);
  ASSERT_GE(contact, 0);
  ASSERT_GE(skip, 0);
  std::size_t first = 0;
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    const auto& row = c.rows[i];
    if (row[contact] == 0.0) {
      EXPECT_EQ(row[defl], 0.0) << "row " << i;
    } else if (first == 0) {
      first = i;
    }
  }
  ASSERT_GT(first, 0U);
  EXPECT_EQ(c.rows[first][skip], 1.0);
  EXPECT_EQ(c.rows[first - 1][skip], 0.0);
  // The touch may fall on the period's end (deflection 0 in that row); the
  // stylus is deflected in the next.
  EXPECT_GE(c.rows[first][defl], 0.0);
  ASSERT_LT(first + 1, c.rows.size());
  EXPECT_GT(c.rows[first + 1][defl], 0.0);
  const double touch = c.rows[first][z] + c.rows[first][defl];
  for (std::size_t i = first; i < c.rows.size() && c.rows[i][contact] == 1.0; ++i) {
    if (i > first && c.rows[i][z] > c.rows[i - 1][z]) break;  // going back up
    EXPECT_NEAR(c.rows[i][z] + c.rows[i][defl], touch, 2e-6) << "row " << i;
  }
}

// The work columns (issue 16) are the actual position in the offsets of the
// block that runs, as #5041.. reads it: a G54 block in G54, the next G55
// block in G55; on Fanuc with the tool length offset in (the gauge line),
// on NCT without it (the programmed tip). The tip column is the gauge line
// less the length of what is in the spindle (the probe: 150 mm to its ball).
TEST(TraceCli, WorkAndTipColumnsFollowTheRunningBlock) {
  TempDir tmp;
  const std::string ex = std::string(SKIPNC_SOURCE_DIR) + "/examples/probing/";
  const auto prog =
      tmp.write("w.nc",
                "G21 G90 G17 G40 G54\nG10 L2 P1 X100. Y50. Z0\n"
                "G43 H20 G0 X10. Y5. Z-200.\nG04 X0.5\nG55 G0 X0 Y0\nG04 X0.5\nM30\n");
  for (const char* dialect : {"fanuc", "nct"}) {
    const auto trace = tmp.path / (std::string(dialect) + ".csv");
    const auto r =
        run_cli({"run", prog.string(), "-s", ex + "fixture.scene.toml", "-m",
                 ex + "mill3_probe.machine.toml", "-d", dialect, "--trace", trace.string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const Csv c = parse_csv(read_file(trace));
    const int line = c.col("line"), xw = c.col("X_work"), yw = c.col("Y_work"),
              zw = c.col("Z_work"), tip = c.col("Z_tip"), za = c.col("Z_act");
    ASSERT_GE(xw, 0);
    ASSERT_GE(tip, 0);
    const bool fanuc = std::string(dialect) == "fanuc";
    bool seen4 = false, seen6 = false;
    for (const auto& row : c.rows) {
      EXPECT_NEAR(row[tip], row[za] - 150.0, 1e-6);
      if (row[line] == 4.0) {  // the dwell after the G54 move: at rest
        seen4 = true;
        EXPECT_NEAR(row[xw], 10.0, 0.001) << dialect;
        EXPECT_NEAR(row[yw], 5.0, 0.001) << dialect;
        EXPECT_NEAR(row[zw], fanuc ? -50.0 : -200.0, 0.001) << dialect;
        EXPECT_NEAR(row[tip], -200.0, 0.001);
      } else if (row[line] == 6.0) {  // after the G55 move
        seen6 = true;
        EXPECT_NEAR(row[xw], 0.0, 0.001) << dialect;
        EXPECT_NEAR(row[yw], 0.0, 0.001) << dialect;
      }
    }
    EXPECT_TRUE(seen4 && seen6);
  }
}

}  // namespace
}  // namespace skipnc::rules
