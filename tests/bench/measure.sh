# Sourced by the peer benches (povray_bench.sh, teem_bench.sh).
#
#   measure TIME_FILE COMMAND...
#
# runs COMMAND three times under /usr/bin/time (its report kept in
# TIME_FILE) and prints the median wall time in seconds and the largest
# peak resident memory in MB: one busy moment on a shared machine moves a
# single run by ±20 %. A run that fails prints "failed 0" at once, with
# the command's standard error kept in TIME_FILE.err for the caller to
# show (POV-Ray stops on 134,000 crowded blob components with an internal
# limit, for one).
measure() {
  local file=$1 times=() peak=0 t m
  shift
  for _ in 1 2 3; do
    if ! /usr/bin/time -f '%e %M' -o "$file" "$@" > /dev/null 2> "$file.err"; then
      echo "failed 0"
      return
    fi
    read -r t m < "$file"
    times+=("$t")
    ((m > peak)) && peak=$m
  done
  echo "$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p) $((peak / 1024))"
}
