// What a reader says when it refuses an input: the InputError's message, or "(accepted)".
#pragma once

#include <string>

#include "io/input_error.hpp"

namespace dda::test {

template <class Read>
std::string refusal_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace dda::test
