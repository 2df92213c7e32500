// girtd regress: RTL against the golden model. The RTL back end is not
// built yet, so asking for it is a usage error rather than a silent pass.
#include "cli/commands.hpp"
#include "common/input_error.hpp"

namespace girtd {

int run_regress(const std::vector<std::string>&) {
  throw InputError("regress", 0, "the rtl back end is not built yet: there is no RTL to regress against golden");
}

}  // namespace girtd
