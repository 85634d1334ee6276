#include "cli/app.hpp"

int main(int argc, char** argv) {
  return rift::cli::run(argc, argv);
}
