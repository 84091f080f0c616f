#include "cli/commands.h"
#include "core/error.h"

namespace cls {
int cmd_citymodel(int, char**) { throw Error("citymodel: not implemented yet"); }
}  // namespace cls
