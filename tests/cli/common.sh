# Sourced by the command-line tests: `hsb` (the program, the first
# argument), `src` (the source tree), `work` (a scratch folder removed on
# exit) and `fail MESSAGE`.
set -uo pipefail
hsb=$1
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
