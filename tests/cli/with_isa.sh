#!/usr/bin/env bash
# with_isa.sh HSB ISA COMMAND...: runs COMMAND with HSB_ISA=ISA, or exits 77
# (CTest's "skipped") when this processor lacks ISA, as `hsb --isa` says.
set -uo pipefail
hsb=$1 isa=$2
shift 2
if ! reason=$("$hsb" --isa "$isa" --version 2>&1); then
  echo "skipped: $reason"
  exit 77
fi
HSB_ISA=$isa exec "$@"
