// Every simulator defines this function (rift_add_simulator generates it):
// it adds the rule packs compiled into the executable to the registry.
#pragma once

namespace rift {
class PackRegistry;
}

void rift_register_packs(rift::PackRegistry& packs);
