#!/usr/bin/env bash
# with_isa.sh HSB ISA COMMAND...: runs COMMAND with HSB_ISA=ISA, or exits 77
# (CTest's "skipped") when this processor lacks ISA, as `hsb --isa` says.
# Any other failure of hsb fails the test.
set -uo pipefail
hsb=$1 isa=$2
shift 2
if ! reason=$("$hsb" --isa "$isa" --version 2>&1); then
  if grep -q "not supported by this processor" <<<"$reason"; then
    echo "skipped: $reason"
    exit 77
  fi
  echo "FAIL: $hsb --isa $isa --version: $reason"
  exit 1
fi
HSB_ISA=$isa exec "$@"
