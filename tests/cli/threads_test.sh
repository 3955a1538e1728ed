#!/usr/bin/env bash
# A process without room for the threads a run starts (ulimit -u counts
# every thread of the user's processes) is refused with one message and
# exit 1, where it died of std::system_error, TBB's std::terminate or
# GLib's SIGTRAP, or hung in log4cplus; with room for a few, TBB is kept to
# them and the picture is drawn. ulimit -u does not bind root: as root the
# runs are made as nobody (setpriv, which execs: no process is added);
# skipped (77) where that cannot be.
source "$(dirname "$0")/common.sh"
hsb=$(realpath "$hsb")
scene=$src/scenes/fig05_point_load_linear.toml
helix=$src/scenes/data/formats/teem_helix.nrrd
size=(--set render.width=32 --set render.height=32)
skip() { echo "skipped: $*"; exit 77; }

as_user=()
if [[ $(id -u) -eq 0 ]]; then
  command -v setpriv > /dev/null || skip "no setpriv to run as nobody (ulimit -u does not bind root)"
  as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  chmod 777 "$work"
  "${as_user[@]}" test -x "$hsb" -a -r "$scene" -a -r "$helix" ||
    skip "nobody cannot reach $hsb and the scenes"
fi

# `limit` and the command after it, as the user (or nobody), without a
# process in between: stderr to $work/err, stdout to $work/out.
limited() {
  local limit=$1
  shift
  "${as_user[@]}" bash -c 'ulimit -u "$0" && exec "$@"' "$limit" "$@" > "$work/out" 2> "$work/err"
}

# No room at all: one message, exit 1, no picture.
limited 1 "$hsb" --threads 1 render "$scene" "${size[@]}" -o "$work/none"
status=$?
[[ $status == 1 ]] || fail "ulimit -u 1: exit $status: $(cat "$work/err")"
[[ $(grep -c . "$work/err") == 1 ]] || fail "ulimit -u 1: not one message: $(cat "$work/err")"
grep -q "cannot start a thread (ulimit -u?)" "$work/err" || fail "ulimit -u 1: $(cat "$work/err")"
[[ ! -e $work/none/fig05_point_load_linear.png ]] || fail "ulimit -u 1: a picture was written"

# Reading a volume (TBB's loops) before any render: the same message.
limited 1 "$hsb" info "$helix"
status=$?
[[ $status == 1 ]] || fail "info under ulimit -u 1: exit $status: $(cat "$work/err")"
grep -q "cannot start a thread (ulimit -u?)" "$work/err" || fail "info under ulimit -u 1: $(cat "$work/err")"

# Room for the threads beside TBB's (base/thread_room.h) and no more: TBB
# keeps to the main thread, on a machine of any size, and the picture is
# drawn. Only as nobody, who has no other process: a user's own (this
# test's shell, the tests run beside it) count against the limit too.
((${#as_user[@]})) || { echo "threads: ok (room for a few: not tried, as a user with other processes)"; exit 0; }
limited 9 "$hsb" render "$scene" "${size[@]}" -o "$work/some"
status=$?
[[ $status == 0 ]] || fail "ulimit -u 9: exit $status: $(cat "$work/err")"
[[ -s $work/some/fig05_point_load_linear.png ]] || fail "ulimit -u 9: no picture"
echo "threads: ok"
