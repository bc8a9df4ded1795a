# Sourced by the comparison benches: measure LABEL COMMAND... runs COMMAND with its
# output in $work/LABEL.log, prints its wall time, CPU time (user + system, its child
# processes included) and peak resident memory, and leaves the seconds in
# $work/LABEL.secs for the ratio: the fastest of the runs of LABEL so far, since on a
# shared machine the slower runs measure the neighbours. The least CPU time so far goes
# to $work/LABEL.cpu: a program that runs on all cores is not compared with a
# single-threaded one by its wall time alone. The peak memory of the largest run so far
# goes to $work/LABEL.kb (memory does not depend on the neighbours: the largest run is
# the one a user must plan for). Needs $work and GNU time (/usr/bin/time).
measure() {
  local label="$1"; shift
  /usr/bin/time -f "%e %M %U %S" -o "$work/time.txt" "$@" > "$work/$label.log" 2>&1 || true
  read -r secs kb user sys < "$work/time.txt"
  local cpu
  cpu=$(printf "%.2f" "$(echo "$user + $sys" | bc -l)")
  printf "%-8s wall %8.2f s   cpu %8.2f s   peak RSS %8.1f MB\n" "$label" "$secs" "$cpu" "$(echo "$kb / 1024" | bc -l)"
  if [ ! -f "$work/$label.secs" ] || [ "$(echo "$secs < $(cat "$work/$label.secs")" | bc -l)" = 1 ]; then
    echo "$secs" > "$work/$label.secs"
  fi
  if [ ! -f "$work/$label.cpu" ] || [ "$(echo "$cpu < $(cat "$work/$label.cpu")" | bc -l)" = 1 ]; then
    echo "$cpu" > "$work/$label.cpu"
  fi
  if [ ! -f "$work/$label.kb" ] || [ "$kb" -gt "$(cat "$work/$label.kb")" ]; then
    echo "$kb" > "$work/$label.kb"
  fi
}

ratio() {  # ratio A B: seconds of A over seconds of B
  echo "$(cat "$work/$1.secs") / $(cat "$work/$2.secs")" | bc -l | cut -c1-5
}

cpu_ratio() {  # cpu_ratio A B: the least CPU seconds of A over those of B
  echo "$(cat "$work/$1.cpu") / $(cat "$work/$2.cpu")" | bc -l | cut -c1-5
}

memory_ratio() {  # memory_ratio A B: the peak memory of A's largest run over B's
  printf "%.3f" "$(echo "$(cat "$work/$1.kb") / $(cat "$work/$2.kb")" | bc -l)"
}
