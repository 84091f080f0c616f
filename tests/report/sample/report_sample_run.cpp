// report_sample_run DIR: writes the sample run directory of tests/report/sample_run.h into DIR (replacing
// it) and its report; the browser test (tests/report/browser_check.py) opens that page.
#include <cstdio>
#include <filesystem>
#include <exception>

#include "report/report.h"
#include "report/sample_run.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: report_sample_run DIR\n");
    return 2;
  }
  try {
    std::filesystem::remove_all(argv[1]);
    cls::test::write_sample_run(argv[1], "synthetic");
    std::printf("%s\n", cls::write_report(argv[1]).string().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report_sample_run: %s\n", e.what());
    return 1;
  }
  return 0;
}
