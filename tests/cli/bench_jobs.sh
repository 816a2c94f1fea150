#!/usr/bin/env bash
# `pagor bench --jobs 2` and `pagor sweep --jobs 2` give what --jobs 1 gives, line for line, times
# aside; a --jobs 2 bench killed mid-run keeps every finished pair once in FILE.partial, and
# --resume ends with the file --jobs 1 writes.
# usage: bench_jobs.sh PAGOR KITTI_ROOT SEMREG_MANIFEST SEMREG_CONFIG WORK_DIR
set -u
PAGOR=$1 KITTI=$2 MANIFEST=$3 CONFIG=$4 WORK=$5
rm -rf "$WORK" && mkdir -p "$WORK"
fail() { echo "FAIL: $*"; exit 1; }
. "$(dirname "$0")/kill_mid_run.sh"
# A results file without its times: every key ending in _ms (timings_ms, the diagnosis' time_ms,
# each level's clique_time_ms) removed.
untimed() { sed -E 's/"[a-z_]*_ms":(\{[^}]*\}|[-+.0-9eE]+),?//g' "$1"; }
# The rows of a bench's output without the time column (8th), up to the summary.
rows() { awk '/^$/ {exit} NR > 1 {$8 = ""; print}' "$1"; }

# 1. The semreg-dev set (ten pairs, five known negatives), one job and two.
"$PAGOR" bench --manifest "$MANIFEST" --config "$CONFIG" --out "$WORK/one.jsonl" >"$WORK/one.log" 2>&1 ||
  fail "--jobs 1: $(tail -1 "$WORK/one.log")"
"$PAGOR" bench --manifest "$MANIFEST" --config "$CONFIG" --jobs 2 --out "$WORK/two.jsonl" >"$WORK/two.log" 2>&1 ||
  fail "--jobs 2: $(tail -1 "$WORK/two.log")"
pairs=$(grep -cv '^ *\(#\|$\)' "$MANIFEST")
[ "$(wc -l <"$WORK/one.jsonl")" -eq "$pairs" ] || fail "--jobs 1 wrote $(wc -l <"$WORK/one.jsonl") lines, not $pairs"
[ "$(untimed "$WORK/one.jsonl")" = "$(untimed "$WORK/two.jsonl")" ] || fail "--jobs 2 wrote other lines than --jobs 1"
[ "$(untimed "$WORK/one.jsonl")" != "$(cat "$WORK/one.jsonl")" ] || fail "no timings were stripped"
[ "$(rows "$WORK/one.log")" = "$(rows "$WORK/two.log")" ] || fail "--jobs 2 printed other rows than --jobs 1"
[ "$(rows "$WORK/one.log" | wc -l)" -eq "$pairs" ] || fail "not one row per pair"
grep -q "^success (selected pose.*): 10/10" "$WORK/two.log" || fail "--jobs 2 summary: $(grep success "$WORK/two.log")"
echo "bench: --jobs 2 equals --jobs 1 on $pairs pairs"

# 2. A pair that fails fails its row only, with --jobs 2 as with 1.
grep -v '^#' "$MANIFEST" | head -3 | sed "s#\.\./\.\./\.\./shared#$(cd "$(dirname "$MANIFEST")/../../../shared" && pwd)#g" >"$WORK/with_missing.txt"
echo "$WORK/nope.pcd $WORK/nope.pcd name=missing" >>"$WORK/with_missing.txt"
touch "$WORK/nope.pcd"
"$PAGOR" bench --manifest "$WORK/with_missing.txt" --config "$CONFIG" --jobs 2 >"$WORK/missing.log" 2>&1 ||
  fail "a failing pair stopped --jobs 2: $(tail -1 "$WORK/missing.log")"
grep -q "^missing .*failed: .*nope.pcd" "$WORK/missing.log" || fail "no failed row naming the file: $(cat "$WORK/missing.log")"
[ "$(rows "$WORK/missing.log" | grep -vc failed)" -eq 3 ] || fail "the other pairs did not run"
echo "bench: a failing pair fails its row only"

# 3. Killed with --jobs 2 after the first finished pair, then resumed with --jobs 2.
cfg="$WORK/slow.json"
write_slow_pair_config "$cfg"
ref="$WORK/ref.jsonl" out="$WORK/killed.jsonl"
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$cfg" --out "$ref" >"$WORK/ref.log" 2>&1 ||
  fail "reference run: $(tail -1 "$WORK/ref.log")"
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$cfg" --jobs 2 --out "$out" >"$WORK/killed.log" 2>&1 &
kill_after_first_pair $! "$out"
[ ! -e "$out" ] || fail "the killed run wrote $out"
[ "$(grep -o '"pair":"[^"]*"' "$out.partial" | sort | uniq -d)" = "" ] || fail "a pair twice in $out.partial"
done_before=$(wc -l <"$out.partial")
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$cfg" --jobs 2 --out "$out" --resume >"$WORK/resumed.log" 2>&1 ||
  fail "resume: $(tail -1 "$WORK/resumed.log")"
grep -q "of which $done_before taken from" "$WORK/resumed.log" || fail "resume did not take the $done_before finished pair(s)"
[ "$(untimed "$ref")" = "$(untimed "$out")" ] || fail "the resumed --jobs 2 file differs from --jobs 1's"
echo "bench: killed after $done_before pair(s) with --jobs 2, resumed to the --jobs 1 file"

# 4. The sweep: two settings of mu over the semreg-dev set.
for j in 1 2; do
  "$PAGOR" sweep --manifest "$MANIFEST" --config "$CONFIG" --mu 0.5,1 --jobs $j --out "$WORK/sweep$j.jsonl" >"$WORK/sweep$j.log" 2>&1 ||
    fail "sweep --jobs $j: $(tail -1 "$WORK/sweep$j.log")"
done
swept() { sed -E 's/"(mean_time_ms|wall_ms)":[^,}]*,?//g' "$1"; }
[ "$(swept "$WORK/sweep1.jsonl")" = "$(swept "$WORK/sweep2.jsonl")" ] || fail "sweep --jobs 2 differs from --jobs 1"
[ "$(wc -l <"$WORK/sweep2.jsonl")" -eq 2 ] || fail "sweep: not one line per setting"
grep -q "stage runs" "$WORK/sweep2.log" && [ "$(grep "stage runs" "$WORK/sweep1.log")" = "$(grep "stage runs" "$WORK/sweep2.log")" ] ||
  fail "sweep --jobs 2 ran other stages: $(grep "stage runs" "$WORK/sweep2.log")"
echo "sweep: --jobs 2 equals --jobs 1"

# 5. A bad --jobs is a usage error naming it.
"$PAGOR" bench --manifest "$MANIFEST" --jobs 0 >/dev/null 2>"$WORK/err"; code=$?
[ $code -eq 2 ] && grep -q -- "--jobs.*'0'" "$WORK/err" || fail "--jobs 0: exit $code, $(cat "$WORK/err")"
echo PASS
