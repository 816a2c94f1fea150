#!/usr/bin/env bash
# Self-similar scenes as a set for the bench (issue 33): `pagor self-similar` writes one seed's 16
# scenes (corridor, facades, sliding street, symmetric hall; with and without distinct objects;
# labelled and not) with their truth and a manifest, and `pagor bench` scores them like any set:
# no pose the truth calls wrong is accepted; the rows and the summary count every scene.
# usage: self_similar_bench.sh PAGOR WORK_DIR
set -u
PAGOR=$1 WORK=$2
rm -rf "$WORK" && mkdir -p "$WORK"
fail() { echo "FAIL: $*"; exit 1; }

"$PAGOR" self-similar --out "$WORK/set" --seeds 1 >"$WORK/gen.log" 2>&1 || fail "self-similar: $(cat "$WORK/gen.log")"
grep -q "wrote 16 scenes" "$WORK/gen.log" || fail "no count: $(cat "$WORK/gen.log")"
for f in pairs.txt corridor-1/source.pcd corridor-1+objects-xyz/target.pcd \
         symmetric-hall-1/T_target_source.txt; do
  [ -s "$WORK/set/$f" ] || fail "missing $f"
done
[ "$(grep -vc '^#' "$WORK/set/pairs.txt")" -eq 16 ] || fail "the manifest should list 16 pairs"
# The labelled scenes name their numbering (detection takes a corridor for the learning map).
[ "$(grep -c ' scheme=semantickitti-train ' "$WORK/set/pairs.txt")" -eq 8 ] ||
  fail "the 8 labelled scenes should name their numbering: $(cat "$WORK/set/pairs.txt")"
grep -- '-xyz/' "$WORK/set/pairs.txt" | grep -q 'scheme=' && fail "an x y z scene names a numbering"

"$PAGOR" bench --manifest "$WORK/set/pairs.txt" --out "$WORK/rows.jsonl" >"$WORK/bench.log" 2>&1 ||
  fail "bench: $(cat "$WORK/bench.log")"
[ "$(wc -l <"$WORK/rows.jsonl")" -eq 16 ] || fail "16 result lines expected: $(cat "$WORK/bench.log")"
grep -q "WRONG POSE ACCEPTED" "$WORK/bench.log" && fail "a wrong pose was accepted: $(cat "$WORK/bench.log")"
grep -Eq "success \(selected pose[^:]*: [0-9]+/16" "$WORK/bench.log" ||
  fail "no success line over 16 scenes: $(cat "$WORK/bench.log")"

out=$("$PAGOR" self-similar --out "$WORK/x" --seeds 0 2>&1)
[ $? -eq 2 ] || fail "--seeds 0 should be a usage error (exit 2): $out"
echo "$out" | grep -q -- "--seeds must be in \[1, 1000\]" || fail "message: $out"
echo PASS
