// The one error type of bad input: every reader throws it with the file and the place in it
// (e.g. "scene.json: blocks[3].vertices: ..."); the command line turns it into exit code 2.
#pragma once

#include <stdexcept>

namespace dda {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace dda
