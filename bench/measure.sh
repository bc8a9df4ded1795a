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
  keep_least "$work/$label.secs" "$secs"
  keep_least "$work/$label.cpu" "$cpu"
  if [ ! -f "$work/$label.kb" ] || [ "$kb" -gt "$(cat "$work/$label.kb")" ]; then
    echo "$kb" > "$work/$label.kb"
  fi
}

keep_least() {  # keep_least FILE VALUE: VALUE into FILE unless FILE holds a smaller one
  if [ ! -f "$1" ] || [ "$(echo "$2 < $(cat "$1")" | bc -l)" = 1 ]; then
    echo "$2" > "$1"
  fi
}

ratio() {  # ratio A B [secs|cpu]: A's fastest wall seconds (or least CPU seconds) over B's
  local kind="${3:-secs}"
  printf "%.3f" "$(echo "$(cat "$work/$1.$kind") / $(cat "$work/$2.$kind")" | bc -l)"
}

memory_ratio() {  # memory_ratio A B: the peak memory of A's largest run over B's
  printf "%.3f" "$(echo "$(cat "$work/$1.kb") / $(cat "$work/$2.kb")" | bc -l)"
}
