# Set-up shared by the command-line tests (tests/cli/test_*.sh), sourced by each right after its
# `set` line; it keeps the caller's shell options. Every test is run by ctest as
#   bash test_NAME.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
# and gets:
#   exe         the pianoaction executable, as an absolute path
#   source_dir  the project's source directory, as an absolute path
#   work        a fresh scratch directory, made the current one and removed on exit
exe="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
source_dir="$(cd "$2" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
