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
