#!/usr/bin/env bash
# Indoor re-localization end to end: `pagor indoor` writes a short generated sequence and reports
# the column detector, `pagor bench` runs its manifest (scans against the floor plan) and
# `--compare-thresholds` prints the pyramid against its single thresholds and the max-clique
# baseline; a malformed plan is one error line naming the element.
# usage: indoor_bench.sh PAGOR WORK_DIR TEST_DATA_DIR
set -u
PAGOR=$1 WORK=$2 DATA=$3
rm -rf "$WORK" && mkdir -p "$WORK"
fail() { echo "FAIL: $*"; exit 1; }

"$PAGOR" indoor --out "$WORK/seq" --scans 8 --seed 2 >"$WORK/gen.log" 2>&1 || fail "indoor: $(cat "$WORK/gen.log")"
grep -q "column detector: recall" "$WORK/gen.log" || fail "no detector figures: $(cat "$WORK/gen.log")"
for f in plan.json built.json pairs.txt poses.txt scans/000007.bin gt/000007.txt; do
  [ -s "$WORK/seq/$f" ] || fail "missing $f"
done

"$PAGOR" bench --manifest "$WORK/seq/pairs.txt" --preset indoor >"$WORK/bench.log" 2>&1 || fail "bench: $(cat "$WORK/bench.log")"
grep -Eq "success \(selected pose, 1\.0 m / 3\.0 deg\): [0-9]+/8" "$WORK/bench.log" ||
  fail "no success line: $(cat "$WORK/bench.log")"
# Measured 6/8 on these scans; the floor sits below.
n=$(sed -nE 's/.*success \(selected pose[^:]*: ([0-9]+)\/8.*/\1/p' "$WORK/bench.log")
[ "${n:-0}" -ge 4 ] || fail "only $n/8 re-localized"

"$PAGOR" bench --manifest "$WORK/seq/pairs.txt" --preset indoor --compare-thresholds >"$WORK/cmp.log" 2>&1 ||
  fail "compare: $(cat "$WORK/cmp.log")"
for v in "pyramid (5 levels)" "single 0.05" "single 0.25" "max clique 0.10"; do
  grep -q "^$v " "$WORK/cmp.log" || fail "no row '$v': $(cat "$WORK/cmp.log")"
done

# A floor-plan target without --preset or --config runs the indoor preset, and says so (the
# defaults' classes are not the indoor scheme's: this was an error naming the class 'car').
out=$("$PAGOR" register --source "$WORK/seq/scans/000001.bin" --target "$WORK/seq/plan.json" 2>&1) ||
  fail "register on a plan without a preset: $out"
echo "$out" | grep -q "^preset: indoor (the target is a floor plan" || fail "no preset line: $out"
echo "$out" | grep -q "^verdict: " || fail "no verdict: $out"
out=$("$PAGOR" bench --manifest "$WORK/seq/pairs.txt" 2>&1) || fail "bench without a preset: $out"
[ "$(echo "$out" | grep -c '^preset: indoor')" -eq 1 ] || fail "bench: no preset line: $out"
grep -E "^success" "$WORK/bench.log" > "$WORK/with_preset.txt"
echo "$out" | grep -E "^success" | cmp -s - "$WORK/with_preset.txt" ||
  fail "bench without a preset differs from --preset indoor: $out"

out=$("$PAGOR" register --source "$WORK/seq/scans/000000.bin" --target "$DATA/bad_plan.json" --preset indoor 2>&1)
[ $? -eq 1 ] || fail "a bad plan should exit with 1: $out"
echo "$out" | grep -q "bad_plan.json: columns\[1\].radius: expected a number" || fail "message: $out"
echo PASS
