#!/usr/bin/env bash
# The front end's report, one row per shared set and variant: success of the selected pose, the
# upper bound (any level), the verdict's precision and recall, the negatives accepted, and the
# median time a pair. Variants are derived here, never stored:
# - semreg-dev labelled, with no configuration at all (the label scheme detected per cloud);
# - semreg-dev raw-id: its labels rewritten as raw SemanticKITTI ids with random instance bits
#   (written to a temporary directory as .label files beside a generated manifest);
# - semreg-dev unlabelled: `label_scheme: none`, the clouds read as x y z only;
# - gedi-dev alone: the matcher's correspondences with the semreg-dev clouds for verification;
# - gedi-dev fused: the same with --fuse, the clouds' landmark correspondences beside them.
# Every semreg-dev variant runs 15 negatives: each source against every target five or more pairs
# later (~100-200 m away, nothing shared); precision counts an accepted negative as wrong.
# Usage: bench/front_end_report.sh [build/app/pagor]
set -euo pipefail
cd "$(dirname "$0")/.."
PAGOR=$(realpath "${1:-build/app/pagor}")
SHARED=$(realpath ../shared/data)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pairs=(03 04 05 06 07 08 09 10 11 12)

# A manifest of the ten pairs and the 15 negatives; $1: the directory of the label files of the
# raw-id variant (empty: the clouds' own labels).
manifest() {
  local labels=$1 i j s t
  for i in "${!pairs[@]}"; do
    s=${pairs[$i]}
    echo -n "$SHARED/semreg-dev/$s/source.pcd $SHARED/semreg-dev/$s/target.pcd"
    echo -n " gt=$SHARED/semreg-dev/$s/T_target_source.txt name=$s"
    [ -n "$labels" ] && echo -n " source_labels=$labels/$s.source.label target_labels=$labels/$s.target.label"
    echo
  done
  for i in "${!pairs[@]}"; do
    for ((j = i + 5; j < ${#pairs[@]}; j++)); do
      s=${pairs[$i]} t=${pairs[$j]}
      echo -n "$SHARED/semreg-dev/$s/source.pcd $SHARED/semreg-dev/$t/target.pcd name=$s-vs-$t overlap=no"
      [ -n "$labels" ] && echo -n " source_labels=$labels/$s.source.label target_labels=$labels/$t.target.label"
      echo
    done
  done
}

# Raw SemanticKITTI labels of every semreg-dev cloud (learning map -> raw ids, instance bits from a
# fixed seed), as .label files.
raw_labels() {
  python3 - "$SHARED/semreg-dev" "$1" <<'EOF'
import os, random, struct, sys
raw = [0, 10, 11, 15, 18, 20, 30, 31, 32, 40, 44, 48, 49, 50, 51, 70, 71, 72, 80, 81]
rng = random.Random(5)
root, out = sys.argv[1], sys.argv[2]
for pair in sorted(p for p in os.listdir(root) if os.path.isdir(os.path.join(root, p))):
    for side in ("source", "target"):
        data = open(os.path.join(root, pair, side + ".pcd"), "rb").read()
        body = data.index(b"DATA binary\n") + len(b"DATA binary\n")
        header = data[:body].decode().split("\n")
        n = int(next(l for l in header if l.startswith("POINTS")).split()[1])
        labels = struct.unpack_from("<" + "12xI" * n, data, body)
        with open(os.path.join(out, pair + "." + side + ".label"), "wb") as f:
            f.write(struct.pack("<%dI" % n, *[raw[l] | rng.randrange(1 << 16) << 16 for l in labels]))
EOF
}

# One row from `pagor bench --out` lines.
row() {
  python3 - "$1" "$2" <<'EOF'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
pos = [r for r in rows if not r.get("negative")]
neg = [r for r in rows if r.get("negative")]
ok = lambda r: bool(r["ground_truth"] and r["ground_truth"]["success"])
acc = lambda r: r["acceptance"]["accepted"]
succ = sum(ok(r) for r in pos)
bound = sum(bool(r["ground_truth"] and r["ground_truth"]["upper_bound"]) for r in pos)
true_acc = sum(ok(r) and acc(r) for r in pos)
accepted = sum(acc(r) for r in rows)
prec = "%.0f %%" % (100.0 * true_acc / accepted) if accepted else "n/a"
rec = "%.0f %%" % (100.0 * true_acc / succ) if succ else "n/a"
fails = " ".join(r["pair"] for r in pos if not ok(r)) or "-"
med = statistics.median(r["timings_ms"]["total"] for r in rows)
print("%-28s %7s %7s %9s %7s %6s %9.0f  %s" % (sys.argv[2], "%d/%d" % (succ, len(pos)),
      "%d/%d" % (bound, len(pos)), prec, rec, "%d/%d" % (sum(acc(r) for r in neg), len(neg)),
      med, fails))
EOF
}

bench() {  # $1 name, $2 config JSON, rest: the pair set
  local name=$1 config=$2
  shift 2
  echo "$config" > "$tmp/config.json"
  "$PAGOR" bench "$@" --config "$tmp/config.json" --out "$tmp/out.jsonl" > /dev/null 2>&1
  row "$tmp/out.jsonl" "$name"
}

printf '%-28s %7s %7s %9s %7s %6s %9s  %s\n' set success bound precision recall negacc "median ms" \
  "failed pairs"
if [ -d "$SHARED/kitti" ]; then
  bench "KITTI dev" '{}' --kitti-root "$SHARED/kitti" --pairs "$SHARED/kitti/pairs_00_dev.txt"
fi
[ -d "$SHARED/semreg-dev" ] || exit 0
manifest "" > "$tmp/semreg.txt"
bench "semreg-dev, no configuration" '{}' --manifest "$tmp/semreg.txt"
mkdir "$tmp/raw" && raw_labels "$tmp/raw" && manifest "$tmp/raw" > "$tmp/raw.txt"
bench "semreg-dev raw ids" '{}' --manifest "$tmp/raw.txt"
bench "semreg-dev unlabelled" '{"label_scheme": "none"}' --manifest "$tmp/semreg.txt"

[ -d "$SHARED/gedi-dev" ] || exit 0
# $1 name, rest: more arguments of `register --correspondences` (e.g. --fuse).
gedi() {
  local name=$1 p
  shift
  rm -f "$tmp/gedi.txt"
  for p in "${pairs[@]}"; do
    "$PAGOR" register --correspondences "$SHARED/gedi-dev/$p.txt" "$@" \
      --source "$SHARED/semreg-dev/$p/source.pcd" --target "$SHARED/semreg-dev/$p/target.pcd" \
      --ground-truth "$SHARED/gedi-dev/$p.T.txt" --json "$tmp/g.json" > /dev/null 2>&1
    python3 - "$tmp/g.json" "$p" >> "$tmp/gedi.txt" <<'EOF'
import json, sys
j = json.load(open(sys.argv[1]))
sel = j["selected_level"]
ok = sel is not None and bool(j["levels"][sel].get("success"))
print(sys.argv[2], int(ok), int(j["acceptance"]["accepted"]), j["timings_ms"]["total"])
EOF
  done
  python3 - "$tmp/gedi.txt" "$name" <<'EOF'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
ok = [r[0] for r in rows if r[1] == "1"]
true_acc = sum(r[1] == "1" and r[2] == "1" for r in rows)
accepted = sum(r[2] == "1" for r in rows)
prec = "%.0f %%" % (100.0 * true_acc / accepted) if accepted else "n/a"
rec = "%.0f %%" % (100.0 * true_acc / len(ok)) if ok else "n/a"
fails = " ".join(r[0] for r in rows if r[1] != "1") or "-"
print("%-28s %7s %7s %9s %7s %6s %9.0f  %s" % (sys.argv[2], "%d/%d" % (len(ok), len(rows)),
      "-", prec, rec, "-", statistics.median(float(r[3]) for r in rows), fails))
EOF
}
gedi "gedi-dev alone (matcher)"
gedi "gedi-dev fused (--fuse)" --fuse
