#!/usr/bin/env bash
# Nothing lost: `pagor bench --out` killed mid-run leaves the previous file intact and every
# finished pair in FILE.partial; `--resume` continues where it stopped; `--json` under a file-size
# limit fails with one line and keeps the previous result.
# usage: bench_resume.sh PAGOR KITTI_ROOT WORK_DIR
set -u
PAGOR=$1 KITTI=$2 WORK=$3
rm -rf "$WORK" && mkdir -p "$WORK"
fail() { echo "FAIL: $*"; exit 1; }
. "$(dirname "$0")/kill_mid_run.sh"

out="$WORK/results.jsonl"
echo '{"previous": "run"}' >"$out"
cfg="$WORK/slow.json"
write_slow_pair_config "$cfg"
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$cfg" --out "$out" >"$WORK/run1.log" 2>&1 &
kill_after_first_pair $! "$out"
[ "$(cat "$out")" = '{"previous": "run"}' ] || fail "the killed run changed $out"
done_before=$(wc -l <"$out.partial")
echo "killed after $done_before finished pair(s); $out intact"

# Simulate a kill in the middle of writing a line: an incomplete last line is dropped on resume.
printf '{"pair": [0, ' >>"$out.partial"
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$cfg" --out "$out" --resume >"$WORK/run2.log" 2>&1 ||
  fail "resume failed: $(tail -1 "$WORK/run2.log")"
grep -q "of which $done_before taken from" "$WORK/run2.log" || fail "resume did not skip the $done_before finished pair(s)"
[ ! -e "$out.partial" ] || fail "$out.partial left behind"
pairs=$(grep -cv '^ *\(#\|$\)' "$KITTI/pairs_00_dev.txt")
[ "$(grep -c '"run_key"' "$out")" -eq "$pairs" ] || fail "$out does not hold one line per pair"
grep -q previous "$out" && fail "$out still holds the old run"
echo "resumed: $out holds $pairs lines"

# A second resume runs nothing: every pair is there for this configuration.
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$cfg" --out "$out" --resume >"$WORK/run3.log" 2>&1 ||
  fail "second resume failed"
grep -q "of which $pairs taken from" "$WORK/run3.log" || fail "second resume re-ran pairs"
# Each line carries the pair's diagnosis, and a resumed pair keeps its verdict column.
[ "$(grep -c '"diagnosis":{"' "$out")" -eq "$pairs" ] || fail "$out lacks a diagnosis per pair"
[ "$(grep -Ec 'resumed +(success|too-few-true|not-consistent|clique-missed|pose-wrong|verification-wrong)$' "$WORK/run3.log")" -eq "$pairs" ] ||
  fail "a resumed pair lost its diagnosis verdict"

# --json under a 4 KiB file-size limit: one error line, exit 1, the previous result kept.
json="$WORK/result.json"
echo '{"good": "previous"}' >"$json"
(ulimit -f 4; "$PAGOR" register --synthetic 7 --json "$json" >/dev/null 2>"$WORK/err"); code=$?
[ $code -eq 1 ] || fail "register --json under ulimit -f exited $code"
# (warnings about the scene may come before it; exactly one error line)
[ "$(grep -c '^pagor: error' "$WORK/err")" -eq 1 ] &&
  grep -q "result.json: write failed.*previous file, if any, is unchanged" "$WORK/err" &&
  ! grep -qv '^pagor: \(error\|warning\): ' "$WORK/err" ||
  fail "unexpected message: $(cat "$WORK/err")"
[ "$(cat "$json")" = '{"good": "previous"}' ] || fail "the previous result was damaged"
[ "$(ls -A "$WORK" | grep -c '^\.result')" -eq 0 ] || fail "a temporary file was left behind"
# bench --out under the same limit: exits 1 and keeps the previous file.
(ulimit -f 4; "$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --out "$out" >/dev/null 2>"$WORK/err"); code=$?
[ $code -eq 1 ] || fail "bench --out under ulimit -f exited $code"
grep -q "cannot append a line" "$WORK/err" || fail "unexpected message: $(cat "$WORK/err")"
[ "$(grep -c '"run_key"' "$out")" -eq "$pairs" ] || fail "bench under a size limit damaged $out"
echo "size limit: previous files intact"
echo PASS
