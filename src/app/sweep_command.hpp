// `dda sweep SWEEP.json --out DIR`: one scene's variants (io/sweep_spec.hpp), each run by
// `dda fos` into DIR/variant-NNN (its scene there as scene.json), and a row per variant in
// DIR/sweep.csv. Under mpirun the variants are shared out over the ranks, each rank running
// whole variants alone (docs/sweep.md).
#pragma once

#include <string>

namespace dda {

// Returns 0 when every variant ran (each variant's own exit code is in its row),
// interrupted_exit_code() when a signal stopped the sweep. Throws InputError for a bad sweep
// file or a variant whose scene is bad (before any variant runs, exit 2) and
// std::runtime_error when DIR cannot be written (exit 1).
int sweep_command(const std::string& sweep_path, const std::string& out_dir);

}  // namespace dda
