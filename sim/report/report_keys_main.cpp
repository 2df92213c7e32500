// girtd_report_keys: prints the key table of report.json from the registry
// (report_keys.hpp), the generated section of sim/README.md
// (tools/generated_docs.py writes it there and checks it is current).
#include <cstdio>

#include "report/report_keys.hpp"

int main() {
  std::fputs(girtd::report_keys_markdown().c_str(), stdout);
  return 0;
}
