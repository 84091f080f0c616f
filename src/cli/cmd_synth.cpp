#include "cli/commands.h"
#include "core/error.h"

namespace cls {
int cmd_synth(int, char**) { throw Error("synth: not implemented yet"); }
}  // namespace cls
