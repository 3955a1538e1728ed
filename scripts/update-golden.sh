#!/usr/bin/env bash
# Re-renders the golden scenes and copies the results over tests/golden/*.png.
# Only for changes meant to alter the pictures: look at each changed image and
# say in the commit why it changed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
HSB_UPDATE_GOLDEN=1 ./build/tests/golden/golden_tests
git status --short tests/golden
