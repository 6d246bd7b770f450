#pragma once
// Every subcommand's callback runs its body through guarded(): bad input (InputError) becomes exit
// code 2 and any other failure exit code 1, each with its message on stderr, as `mssph --help`
// documents.
#include "util/errors.hpp"

#include <exception>
#include <iostream>

namespace mssph::cli {

template <typename Body>
void guarded(int& exit_code, Body body) {
  try {
    exit_code = body();
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    exit_code = kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    exit_code = kExitOther;
  }
}

}  // namespace mssph::cli
