// The `dda` program: one command, one subcommand per pipeline stage.
#include <iostream>

#include "dda/common/provenance.hpp"

int main(int argc, char** argv) {
  std::cout << "dda " << dda::version_string() << "\n";
  return 0;
}
