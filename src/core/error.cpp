#include "core/error.h"

namespace cls {

void fail(const std::string& path, const std::string& what) { throw Error(path + ": " + what); }

}  // namespace cls
