// The `rift` executable: the command line with the standard rule packs.
#include "cli/app.hpp"
#include "cli/register_packs.hpp"
#include "rift/pack/pack.hpp"

int main(int argc, char** argv) {
  rift::PackRegistry packs;
  rift_register_packs(packs);
  return rift::cli::run(argc, argv, packs);
}
