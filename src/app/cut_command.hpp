// `dda cut MODEL.json --out SCENE.json`: reads a cutting model, cuts its domain
// into blocks, writes the scene and prints the cut's statistics on stderr.
#pragma once

#include <string>

namespace dda {

// Returns the exit code (0); throws InputError for a bad model (exit 2) and
// std::runtime_error when the scene cannot be written (exit 1), as main reports them.
int cut_command(const std::string& model_path, const std::string& out_path);

}  // namespace dda
