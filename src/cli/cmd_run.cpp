#include "cli/commands.h"
#include "core/error.h"

namespace cls {
int cmd_run(int, char**) { throw Error("run: not implemented yet"); }
}  // namespace cls
