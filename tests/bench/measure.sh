# Sourced by the peer benches (povray_bench.sh, teem_bench.sh).
#
#   measure TIME_FILE COMMAND...
#
# runs COMMAND three times under /usr/bin/time (its report kept in
# TIME_FILE) and prints the median wall time in seconds and the largest
# peak resident memory in MB: one busy moment on a shared machine moves a
# single run by ±20 %.
measure() {
  local file=$1 times=() peak=0 t m
  shift
  for _ in 1 2 3; do
    /usr/bin/time -f '%e %M' -o "$file" "$@" > /dev/null 2>&1
    read -r t m < "$file"
    times+=("$t")
    ((m > peak)) && peak=$m
  done
  echo "$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p) $((peak / 1024))"
}
