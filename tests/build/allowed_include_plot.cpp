// The control of build_forbidden_include_plot and _report: the same target
// set-up compiles with the plot's and the report's own headers and the run's
// vocabulary.
#include "plot/recorder.hpp"
#include "record/record.hpp"
#include "report/report.hpp"
#include "sim/simulator.hpp"

int main() {
  return 0;
}
