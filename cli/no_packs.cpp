// Registration for a `rift` built without rule packs (RIFT_BUILD_COMPILER=OFF):
// `rift info` works, `rift run` explains that no interaction is compiled in.
#include "cli/register_packs.hpp"

void rift_register_packs(rift::PackRegistry& /*packs*/) {}
