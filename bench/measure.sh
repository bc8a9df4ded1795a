# Sourced by the comparison benches: measure LABEL COMMAND... runs COMMAND with its
# output in $work/LABEL.log, prints its wall time and peak resident memory, and leaves
# the seconds in $work/LABEL.secs for the ratio. Needs $work and GNU time (/usr/bin/time).
measure() {
  local label="$1"; shift
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" > "$work/$label.log" 2>&1 || true
  read -r secs kb < "$work/time.txt"
  printf "%-8s wall %8.2f s   peak RSS %8.1f MB\n" "$label" "$secs" "$(echo "$kb / 1024" | bc -l)"
  echo "$secs" > "$work/$label.secs"
}

ratio() {  # ratio A B: seconds of A over seconds of B
  echo "$(cat "$work/$1.secs") / $(cat "$work/$2.secs")" | bc -l | cut -c1-5
}
