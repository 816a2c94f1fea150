# Sourced by the CLI scripts that kill a bench mid-run (bench_resume.sh, bench_jobs.sh); they
# define fail().

# Writes to FILE a configuration under which a KITTI pair takes seconds, so that a kill lands
# mid-run. Instrumented builds set PAGOR_TEST_SLOW_PAIR_CONFIG to {}: their defaults are slow enough.
write_slow_pair_config() {
  local finer='{"verification": {"voxel_size": 0.1}, "refinement": {"max_points": 100000}}'
  echo "${PAGOR_TEST_SLOW_PAIR_CONFIG:-$finer}" >"$1"
}

# Waits until OUT.partial holds a finished pair (or process PID has ended), then kills PID without
# warning; fails unless OUT.partial then holds whole lines.
kill_after_first_pair() {
  local pid=$1 out=$2
  for _ in $(seq 1 6000); do
    [ -s "$out.partial" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  [ -s "$out.partial" ] || fail "no finished pair in $out.partial"
  [ "$(tail -c 1 "$out.partial" | od -An -c | tr -d ' ')" = '\n' ] || fail "$out.partial ends inside a line"
}
