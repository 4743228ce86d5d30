# Sourced by the verification scripts (verification/*/run.sh): the one way they find their
# program, so that each says only what it runs. Bash.
#
#   exe="$(verification_program "$0" NAME)" || exit 2
#
# prints $DDA_BUILD_DIR/NAME (default: build/release of this repository) when it is an
# executable, and otherwise says on stderr how to build it and fails.
verification_program() {
  local script="$1" name="$2"
  local root
  root="$(cd "$(dirname "$script")/../.." && pwd)"
  local exe="${DDA_BUILD_DIR:-$root/build/release}/$name"
  if [ ! -x "$exe" ]; then
    echo "$script: $exe not found; build it first (cmake --preset release && cmake --build --preset release --target $name)" >&2
    echo "    or point DDA_BUILD_DIR at a build directory that has it" >&2
    return 1
  fi
  printf '%s\n' "$exe"
}

#   out="$(verification_out_dir "$0" "[--smoke] ..." "$@")" || exit 2; shift
#
# prints the script's first argument, OUT_DIR, when it is one (given, not an option), and
# otherwise prints the usage, with the script's own options, on stderr and fails.
verification_out_dir() {
  local script="$1" options="$2"
  shift 2
  if [ $# -lt 1 ] || [ "${1#-}" != "$1" ]; then
    echo "usage: $script OUT_DIR $options   (env DDA_BUILD_DIR: the build directory, default build/release)" >&2
    return 1
  fi
  printf '%s\n' "$1"
}
