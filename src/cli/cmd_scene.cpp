#include "cli/commands.h"
#include "core/error.h"

namespace cls {
int cmd_scene(int, char**) { throw Error("scene: not implemented yet"); }
}  // namespace cls
