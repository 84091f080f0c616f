#include "cli/commands.h"
#include "core/error.h"

namespace cls {
int cmd_raycast(int, char**) { throw Error("raycast: not implemented yet"); }
}  // namespace cls
