#include "cli/commands.h"
#include "core/error.h"

namespace cls {
int cmd_align_check(int, char**) { throw Error("align_check: not implemented yet"); }
}  // namespace cls
