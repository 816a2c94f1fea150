#!/usr/bin/env bash
# Side-by-side back-end timing: Pagor (the CLI of a build: $PAGOR, default build/app/pagor) vs KISS-Matcher's back end (km_backend).
# Needs ./build.sh to have been run. Writes results/raw/*, results/machine.txt, and results.md.
#
#   ./run.sh            # full run (gedi-dev + 20 generated problems)
#   SETS=gedi ./run.sh  # one set only
#
# Protocol: one CPU (taskset -c $CPU), OpenMP limited to one thread (OMP_NUM_THREADS=1 and
# OMP_THREAD_LIMIT=1: ROBIN's PMC max-clique asks for num_threads(12) explicitly, which only the
# thread limit caps). Per problem, 3 rounds of [ours, peer] in fresh processes, interleaved.
#  ours : pagor register --correspondences F --ground-truth G --json J -> `times [ms]:` line
#         (back end = graph + clique + gnc; best of the 3 processes by that sum; the JSON, written
#          after the pipeline, gives per-level clique times and budget hits)
#  peer : km_backend --corr F --gt G --resolution 0.3 --mode max_core --reps 4
#         (KISS-Matcher default outdoor config; per process: the first run = "cold", best of
#          runs 2-4 = "warm"; peer time used for the ratio = best of the 3 processes' cold runs,
#          i.e. one back-end call per fresh process, like our CLI)
# After the rounds, one extra peer process per problem with --mode max_clique (ROBIN MAX_CLIQUE =
# PMC exact), a non-default KISS-Matcher mode, for reference.
# Finally pagor_bench --only dense (our benchmark: warm, in-process medians of 15) for the gedi set.
set -euo pipefail
REPO=$(cd "$(dirname "$0")/../.." && pwd)
HERE=${PEER_DIR:-$HOME/pagor-peer}
mkdir -p "$HERE"; cd "$HERE"
OURS=${PAGOR:-$REPO/build/app/pagor}
BENCH=${PAGOR_BENCH:-$REPO/build/bench/pagor_bench}
PEER=$HERE/build/harness/km_backend
GEN=$HERE/build/harness/gen_problems
GEDI=${GEDI:-$REPO/../shared/data/gedi-dev}
CPU=${CPU:-0}
SETS=${SETS:-"gedi gen"}
RES=0.3
export OMP_NUM_THREADS=1 OMP_THREAD_LIMIT=1 OMP_DYNAMIC=false
[[ -x $PEER && -x $GEN ]] || { echo "run ./build.sh first" >&2; exit 1; }

OUT=$HERE/results
RAW=$OUT/raw
rm -rf "$RAW"; mkdir -p "$RAW" "$HERE/problems/gen"

# (b) generated problems, fixed seeds 1..20
"$GEN" "$HERE/problems/gen" 20 1 > "$HERE/problems/gen/manifest.txt"

{
  echo "start: $(date -Is)"; echo "uptime: $(uptime)"; echo "cpus: $(nproc --all)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2-)"
  echo "taskset cpu: $CPU; OMP_NUM_THREADS=$OMP_NUM_THREADS OMP_THREAD_LIMIT=$OMP_THREAD_LIMIT"
  echo "top at start:"; top -b -n1 | sed -n '1,15p'
} > "$OUT/machine.txt"

problems() { # set -> lines "name corr gt"
  case $1 in
    gedi) for i in 03 04 05 06 07 08 09 10 11 12; do echo "gedi-$i $GEDI/$i.txt $GEDI/$i.T.txt"; done ;;
    gen)  for i in $(seq -w 1 20); do echo "gen-$i $HERE/problems/gen/gen-$i.txt $HERE/problems/gen/gen-$i.T.txt"; done ;;
  esac
}

for set in $SETS; do
  while read -r name corr gt; do
    echo "[$(date +%T)] $name (load $(cut -d' ' -f1 /proc/loadavg))" >&2
    for rep in 1 2 3; do
      taskset -c "$CPU" timeout 600 "$OURS" register --correspondences "$corr" --ground-truth "$gt" \
        --json "$RAW/$name.ours.$rep.json" > "$RAW/$name.ours.$rep.txt" 2>&1 || echo "ours exit $? on $name rep $rep" >> "$RAW/$name.ours.$rep.txt"
      taskset -c "$CPU" "$PEER" --corr "$corr" --gt "$gt" --resolution $RES --mode max_core \
        --reps 4 --name "$name" > "$RAW/$name.peer.$rep.txt" 2>&1 ||
        echo "peer exit $? on $name rep $rep" >> "$RAW/$name.peer.$rep.txt"
    done
    taskset -c "$CPU" "$PEER" --corr "$corr" --gt "$gt" --resolution $RES --mode max_clique \
      --reps 4 --name "$name" > "$RAW/$name.peerclique.txt" 2>&1 ||
      echo "peer exit $? on $name (max clique)" >> "$RAW/$name.peerclique.txt"
    echo "$name load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$RAW/loadavg.txt"
  done < <(problems "$set")
done

# Cold-process experiment (gedi only): the same back ends with glibc's malloc backed by transparent
# huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), i.e. far fewer first-touch page faults, which
# are expensive in this VM guest. Interleaved, 3 processes each; not used for the main ratios.
if [[ " $SETS " == *" gedi "* ]]; then
  while read -r name corr gt; do
    for rep in 1 2 3; do
      GLIBC_TUNABLES=glibc.malloc.hugetlb=1 taskset -c "$CPU" "$OURS" register --correspondences "$corr" \
        --ground-truth "$gt" > "$RAW/$name.ours_thp.$rep.txt" 2>&1 || true
      GLIBC_TUNABLES=glibc.malloc.hugetlb=1 taskset -c "$CPU" "$PEER" --corr "$corr" --gt "$gt" \
        --resolution $RES --mode max_core --reps 4 --name "$name" > "$RAW/$name.peer_thp.$rep.txt" 2>&1
    done
  done < <(problems gedi)
fi

# Our own benchmark binary (warm, in-process medians of 15) on gedi-dev, for reference.
if [[ " $SETS " == *" gedi "* ]]; then
  taskset -c "$CPU" "$BENCH" --only dense --gedi-root "$GEDI" > "$RAW/pagor_bench_dense.txt" 2>&1 || true
fi

{ echo "end: $(date -Is)"; echo "uptime: $(uptime)"; echo "top at end:"; top -b -n1 | sed -n '1,15p'; } >> "$OUT/machine.txt"

python3 "$REPO/bench/peer/summarize.py" > "$HERE/results.md"
echo "wrote $HERE/results.md" >&2
