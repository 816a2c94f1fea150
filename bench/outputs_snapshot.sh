#!/usr/bin/env bash
# The results of every shared set, for checking that a change leaves them as they were (or for
# seeing exactly what it changed): semreg-dev (10 pairs + 5 negatives), the KITTI dev pairs, the
# ten gedi-dev correspondence problems and the generated indoor sequences of seeds 1-3 (120 scans).
# Writes OUT/<set>.jsonl, one result per line, with timings, run keys and the config left out, so
# two binaries' snapshots compare with `diff -r`.
# Usage: bench/outputs_snapshot.sh PAGOR OUT   (e.g. build/app/pagor /tmp/after)
set -euo pipefail
cd "$(dirname "$0")/.."
PAGOR=$(realpath "$1")
OUT=$(mkdir -p "$2" && realpath "$2")
SHARED=../shared/data
strip() {
  python3 -c '
import json, sys
def clean(o):
    if isinstance(o, dict):
        return {k: clean(v) for k, v in o.items()
                if k not in ("timings_ms", "time_ms", "run_key", "tool_version", "config")
                and not k.endswith("_ms")
                and not (k in ("source", "target", "file") and isinstance(v, str))}
    if isinstance(o, list):
        return [clean(x) for x in o]
    return o
for line in sys.stdin:
    if line.strip():
        print(json.dumps(clean(json.loads(line)), sort_keys=True))
'
}
"$PAGOR" bench --manifest bench/manifests/semreg-dev.txt --config bench/manifests/semreg-dev.json \
  --out "$OUT/semreg.raw" > "$OUT/semreg.txt" 2>&1
strip < "$OUT/semreg.raw" > "$OUT/semreg.jsonl"
"$PAGOR" bench --kitti-root "$SHARED/kitti" --sequence 00 --pairs "$SHARED/kitti/pairs_00_dev.txt" \
  --out "$OUT/kitti.raw" > "$OUT/kitti.txt" 2>&1
strip < "$OUT/kitti.raw" > "$OUT/kitti.jsonl"
: > "$OUT/gedi.jsonl"
for f in "$SHARED"/gedi-dev/[0-9][0-9].txt; do
  n=$(basename "$f" .txt)
  "$PAGOR" register --correspondences "$f" --json "$OUT/gedi_$n.json" > "$OUT/gedi_$n.txt" 2>&1 || true
  python3 -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))))' \
    "$OUT/gedi_$n.json" | strip >> "$OUT/gedi.jsonl"
done
for seed in 1 2 3; do
  seq="$OUT/indoor-seed$seed"
  [ -f "$seq/pairs.txt" ] || "$PAGOR" indoor --out "$seq" --scans 120 --seed "$seed" > /dev/null
  "$PAGOR" bench --manifest "$seq/pairs.txt" --preset indoor --out "$OUT/indoor$seed.raw" \
    > "$OUT/indoor$seed.txt" 2>&1
  strip < "$OUT/indoor$seed.raw" > "$OUT/indoor$seed.jsonl"
done
echo "wrote $OUT/{semreg,kitti,gedi,indoor1,indoor2,indoor3}.jsonl"
