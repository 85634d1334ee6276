// Every standard rule pack of rules/ (rules/CMakeLists.txt), registered once,
// for the tests that build scenes as the `rift` command does. Only targets
// that link rift_standard_packs may include this header.
#pragma once

#include "criteria2d.hpp"
#include "criteria3d.hpp"
#include "fem2d.hpp"
#include "fem3d.hpp"
#include "mass_spring2d.hpp"
#include "mass_spring3d.hpp"
#include "rift/pack/pack.hpp"
#include "topology2d.hpp"
#include "topology3d.hpp"

namespace rift::test_support {

inline const PackRegistry& standard_packs() {
  static const PackRegistry packs = [] {
    PackRegistry r;
    rift_register_pack_mass_spring2d(r);
    rift_register_pack_mass_spring3d(r);
    rift_register_pack_fem2d(r);
    rift_register_pack_fem3d(r);
    rift_register_pack_criteria2d(r);
    rift_register_pack_criteria3d(r);
    rift_register_pack_topology2d(r);
    rift_register_pack_topology3d(r);
    return r;
  }();
  return packs;
}

}  // namespace rift::test_support
