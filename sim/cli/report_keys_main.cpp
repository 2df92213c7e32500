// girtd_report_keys: prints the key table of report.json from the key
// registry (report/report_keys.hpp) and the back-end registry
// (engine/backend_registry.hpp), the generated section of sim/README.md
// (tools/generated_docs.py writes it there and checks it is current).
#include <cstdio>

#include "engine/backend_registry.hpp"
#include "report/report_keys.hpp"

int main() {
  std::fputs(girtd::report_keys_markdown(girtd::backend_registry()).c_str(), stdout);
  return 0;
}
