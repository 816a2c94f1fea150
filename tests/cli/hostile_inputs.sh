#!/usr/bin/env bash
# Round two of the hostile inputs (issue 25): each case once gave a result never computed, a hang,
# a crash, a silent wrong answer, a lost result or an overwritten input. Each must now end in the
# right result or one clear error line naming the file; a run that should end is bounded by
# `timeout`. Cases are numbered by the issue's items.
# usage: hostile_inputs.sh PAGOR KITTI_ROOT SEMREG_DIR SOURCE_DIR WORK_DIR
set -u
PAGOR=$1 KITTI=$2 SEMREG=$3 SRC=$4 WORK=$5
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
failures=0 checks=0
SEQ="$KITTI/sequences/00"
SEMCFG="$SRC/bench/manifests/semreg-dev.json"

pass() { checks=$((checks + 1)); echo "ok    $*"; }
fail() { checks=$((checks + 1)); failures=$((failures + 1)); echo "FAIL  $*"; }
# expect CODE "needle1|needle2" command...: exit CODE within 120 s and one stderr line (after any
# warnings) holding every needle.
expect() {
  local want=$1 needles=$2 code lines ok=1
  shift 2
  timeout 120 "$@" >out.log 2>err.log
  code=$?
  lines=$(grep -vc '^pagor: warning: ' err.log)
  [ "$code" -eq "$want" ] && [ "$lines" -eq 1 ] || ok=0
  local IFS='|'
  for n in $needles; do grep -qF -- "$n" err.log || ok=0; done
  if [ $ok -eq 1 ]; then pass "$*"; else
    fail "$*   (exit $code, $lines lines; wanted $want: $needles)"
    head -c 1500 err.log | sed 's/^/      | /'
  fi
}
# check "what" command...: the command succeeds (its output in out.log).
check() {
  local what=$1
  shift
  if timeout 300 "$@" >out.log 2>err.log; then pass "$what"; else
    fail "$what (exit $?)"
    tail -5 err.log | sed 's/^/      | /'
  fi
}
cmp_same() { if cmp -s "$1" "$2"; then pass "$3"; else fail "$3"; fi; }
bench_rows() { grep -cE "^$1 " out.log; }

# Shared inputs.
cp "$SEQ/velodyne/000020.bin" s20.bin && cp "$SEQ/labels/000020.label" s20.label
cp "$SEQ/velodyne/000030.bin" t30.bin && cp "$SEQ/labels/000030.label" t30.label
cp "$SRC/tests/data/kitti_00_20_30_gt.txt" gt.txt
chmod u+w ./*

# ---- 1. two pairs sharing a name ----
printf 's20.bin t30.bin gt=gt.txt name=x\nt30.bin s20.bin name=x\n' >dup.txt
echo previous >r1.jsonl
expect 1 "dup.txt:2: the name 'x' is already used by line 1" "$PAGOR" bench --manifest dup.txt --out r1.jsonl
[ "$(cat r1.jsonl)" = previous ] && pass "1: the results file is untouched" || fail "1: results file changed"
printf '0 20\n20 30\n0 20\n' >dup_pairs.txt
expect 1 "dup_pairs.txt: the pair 0 20 is listed twice" "$PAGOR" bench --kitti-root "$KITTI" --pairs dup_pairs.txt

# ---- 2. results of another data set, configuration or build are not reused ----
mkdir -p other/sequences/00
ln -s "$(cd "$SEQ" && pwd)/velodyne" other/sequences/00/velodyne
ln -s "$(cd "$SEQ" && pwd)/labels" other/sequences/00/labels
cp "$SEQ/calib.txt" other/sequences/00/
awk 'NR==31 {$4 = $4 + 3} {print}' "$SEQ/poses.txt" >other/sequences/00/poses.txt  # frame 30 moved
check "2: bench --out on the shared sequence" "$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --out r2.jsonl
check "2: resume on another data set" "$PAGOR" bench --kitti-root other --pairs "$KITTI/pairs_00_dev.txt" --out r2.jsonl --resume
# 0->20 reads the same files; 20->30 and 0->30 read a moved pose of frame 30... and poses.txt
# differs, so nothing is taken from the stale file.
grep -q "taken from" out.log && fail "2: stale results were reused" || pass "2: no stale result reused"
check "2: resume on the same data" "$PAGOR" bench --kitti-root other --pairs "$KITTI/pairs_00_dev.txt" --out r2.jsonl --resume
grep -q "of which 3 taken from" out.log && pass "2: results of the same data are reused" || fail "2: not reused"
cp "$PAGOR" pagor-rebuilt && printf 'x' >>pagor-rebuilt  # another build of the tool
check "2: resume with another build" ./pagor-rebuilt bench --kitti-root other --pairs "$KITTI/pairs_00_dev.txt" --out r2.jsonl --resume
grep -q "taken from" out.log && fail "2: results of another build were reused" || pass "2: another build reruns"
printf 's20.bin t30.bin gt=gt.txt name=a\n' >m2.txt
check "2: manifest run" "$PAGOR" bench --manifest m2.txt --out r2g.jsonl
cp gt.txt gt.orig
awk 'NR==1 {$4 = $4 + 1} {print}' gt.orig >gt.txt  # the same manifest and paths, another truth
check "2: resume after the ground truth changed" "$PAGOR" bench --manifest m2.txt --out r2g.jsonl --resume
grep -q "taken from" out.log && fail "2: a changed manifest's result was reused" || pass "2: changed content reruns"
cp gt.orig gt.txt

# ---- 3. the same file spelled two ways ----
printf 's20.bin t30.bin gt=gt.txt\n./s20.bin t30.bin gt=gt.txt\n' >spelled.txt
expect 1 "spelled.txt:2: the same pair as line 1" "$PAGOR" bench --manifest spelled.txt
check "3: a run" "$PAGOR" bench --manifest m2.txt --out r3.jsonl
ln -s . here
printf 'here/s20.bin ./t30.bin gt=./gt.txt name=a\n' >m3.txt
check "3: resume with the files spelled another way" "$PAGOR" bench --manifest m3.txt --out r3.jsonl --resume
grep -q "of which 1 taken from" out.log && pass "3: one entry for the pair, reused" || fail "3: not reused"

# ---- 4. two writers of one results file ----
# Seconds per pair (as bench_resume.sh), so that the second writer comes while the first runs.
finer='{"verification": {"voxel_size": 0.1}, "refinement": {"max_points": 100000}}'
echo "${PAGOR_TEST_SLOW_PAIR_CONFIG:-$finer}" >slow.json
"$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config slow.json --out r4.jsonl >w1.log 2>&1 &
pid=$!
for _ in $(seq 1 600); do [ -e r4.jsonl.lock ] && break; sleep 0.05; done
expect 1 "r4.jsonl: is being written by pid $pid" "$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --out r4.jsonl
wait $pid && [ "$(grep -c run_key r4.jsonl)" -eq 3 ] && pass "4: the first writer's results are whole" || fail "4: results lost"

# ---- 5. the rows and the summary agree ----
cp "$SEMREG/03/source.pcd" s03.pcd && cp "$SEMREG/03/target.pcd" t03.pcd && cp "$SEMREG/08/target.pcd" t08.pcd
printf 's03.pcd t03.pcd gt=%s name=truth\ns03.pcd t03.pcd name=notruth overlap=yes\n' "$SEMREG/03/T_target_source.txt" >m5.txt
printf 's03.pcd t08.pcd name=neg overlap=no\nmissing.pcd t03.pcd name=gone\n' >>m5.txt
touch missing.pcd
check "5: bench with and without truth, a negative, a failed pair" "$PAGOR" bench --manifest m5.txt --config "$SEMCFG"
accepts=$(grep -cE '^[a-z]+ .* accept ' out.log)
summary=$(sed -nE 's/^verdict: ([0-9]+) accepted.*/\1/p' out.log)
[ "$accepts" = "$summary" ] && [ "$accepts" -eq 2 ] && pass "5: $accepts rows say accept, the summary counts $summary" ||
  fail "5: $accepts accept rows, summary $summary"
grep -q "of the 2 accepted, 1 without a ground truth" out.log && pass "5: the unjudged accept is named" || fail "5: unjudged accept"
grep -q "^gone  *failed: .*missing.pcd" out.log && grep -q "pairs run: 3 (1 more failed)" out.log &&
  pass "5: the failed pair has its row and count" || fail "5: failed pair row"

# ---- 6. files that never end or block ----
ln -s /dev/zero zero.pcd && ln -s /dev/zero zero.json && ln -s /dev/zero zero.label && ln -s /dev/zero zero.txt
mkfifo fifo.pcd fifo.json fifo.txt fifo.svg
for f in zero fifo; do
  expect 1 "$f.pcd: point cloud is a" "$PAGOR" landmarks --source $f.pcd
  expect 1 "$f.json: config file is a" "$PAGOR" config --check $f.json
  expect 1 "$f.txt: manifest is a" "$PAGOR" bench --manifest $f.txt
  expect 1 "$f.txt: pairs file is a" "$PAGOR" bench --kitti-root "$KITTI" --pairs $f.txt
  expect 1 "$f.txt: transform file is a" "$PAGOR" register --source s20.bin --target t30.bin --ground-truth $f.txt
  expect 1 "$f.txt: correspondences file is a" "$PAGOR" register --correspondences $f.txt
done
expect 1 "zero.label: label file is a" "$PAGOR" landmarks --source s20.bin --source-labels zero.label
expect 1 "zero.json: floor plan is a" "$PAGOR" register --source s20.bin --target zero.json --preset indoor
expect 1 "fifo.svg: floor plan is a" "$PAGOR" register --source s20.bin --target fifo.svg --preset indoor

# ---- 7. a correspondences file beyond the graph's budget ----
python3 -c "
import random
random.seed(1)
with open('corr.txt', 'w') as f:
    for i in range(100000):
        f.write('%f %f %f %f %f %f\n' % tuple(random.uniform(-50, 50) for _ in range(6)))"
expect 1 "corr.txt:20001: more than 20000 correspondences|kMaxGraphCorrespondences" "$PAGOR" register --correspondences corr.txt

# ---- 8. floor plans ----
python3 -c "
import struct
with open('high.bin', 'wb') as f:  # a scan above the height band: fails after the plan is read
    for i in range(100): f.write(struct.pack('<4f', i * 0.1, 0.0, 10.0, 0.0))
with open('scan.bin', 'wb') as f:
    for i in range(400): f.write(struct.pack('<4f', 5.0 + (i % 20) * 0.05, (i // 20) * 0.1, 0.5, 0.0))
walls = ','.join('{\"points\": [[%d, 0], [%d, 0.01]]}' % (i % 1000, i % 1000) for i in range(400000))
open('big.json', 'w').write('{\"walls\": [' + walls + ']}')"
printf '{"walls": [{"points": [[-9e6, 0], [9e6, 0]]}]}' >long.json
expect 1 "long.json: walls[0]: sampling the plan every 0.05 m|10000000 points" "$PAGOR" register --source scan.bin --target long.json --preset indoor
printf "<svg data-scale='1'><circle cx='0' cy='0' r='1e9'/></svg>" >radius.svg
expect 1 "radius.svg:1: <circle> #1: radius" "$PAGOR" register --source scan.bin --target radius.svg --preset indoor
for attr in "<g transform='translate(5 0)'>" "<g style='transform: translate(5px)'>" "<svg x='5'>"; do
  printf "<svg data-scale='1'>%s<rect width='10' height='5'/></g></svg>" "$attr" >placed.svg
  expect 1 "placed.svg:1: <" "$PAGOR" register --source scan.bin --target placed.svg --preset indoor
done
for scale in 0 1e-310 inf; do
  printf "<svg data-scale='%s'><rect width='10' height='5'/></svg>" $scale >scale.svg
  expect 1 "scale.svg:1: <svg> #1: |data-scale" "$PAGOR" register --source scan.bin --target scale.svg --preset indoor
done
expect 1 "high.bin: no scan point lies within the height band" "$PAGOR" register --source high.bin --target big.json --preset indoor

# ---- 9. an interrupted pagor indoor leaves no manifest pairing two runs' files ----
check "9: a complete sequence" "$PAGOR" indoor --out seq --scans 4 --seed 1
"$PAGOR" indoor --out seq --scans 400 --seed 2 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 1200); do [ -e seq/scans/000010.bin ] && break; sleep 0.05; done
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
[ ! -e seq/pairs.txt ] && pass "9: no manifest after the interrupted run" || fail "9: a manifest survived"
bad=0
for f in seq/scans/*.bin; do [ $(($(stat -c %s "$f") % 16)) -eq 0 ] || bad=1; done
[ $bad -eq 0 ] && pass "9: every scan written is whole" || fail "9: a truncated scan"
expect 1 "seq/pairs.txt: manifest does not exist" "$PAGOR" bench --manifest seq/pairs.txt --preset indoor

# ---- 10. an output that is an input ----
cp s20.bin keep.bin
expect 2 "--json ./s20.bin is also an input (--source s20.bin)" "$PAGOR" register --source s20.bin --target t30.bin --json ./s20.bin
ln -s s20.bin alias.bin
expect 2 "--json alias.bin is also an input" "$PAGOR" landmarks --source s20.bin --json alias.bin
expect 2 "--out m2.txt is also an input (--manifest m2.txt)" "$PAGOR" bench --manifest m2.txt --out m2.txt
expect 2 "--out t30.bin is also an input (pair a's target" "$PAGOR" bench --manifest m2.txt --out t30.bin
expect 2 "--out ./gt.txt is also an input (pair a's ground truth" "$PAGOR" bench --manifest m2.txt --out ./gt.txt
expect 2 "--csv sweep.out is also --out" "$PAGOR" sweep --manifest m2.txt --mu 0.5,1 --out sweep.out --csv sweep.out
expect 2 "--json slow.json is also an input (--config slow.json)" "$PAGOR" register --synthetic 7 --config slow.json --json slow.json
cmp_same s20.bin keep.bin "10: the inputs are intact"

# ---- 11. far coordinates ----
python3 - "$SEMREG" <<'PY'
import struct, sys, math
root = sys.argv[1]
def read_pcd(path):
    data = open(path, 'rb').read()
    head, body = data.split(b'DATA binary\n', 1)
    n = int([l for l in head.split(b'\n') if l.startswith(b'POINTS')][0].split()[1])
    return [struct.unpack_from('<3fI', body, 16 * i) for i in range(n)]
c, s = math.cos(0.5), math.sin(0.5)
M = lambda p: (c * p[0] - s * p[1] + 300000.0, s * p[0] + c * p[1] + 4500000.0, p[2] + 52.0)
for name, src in (('far_s.pcd', '/03/source.pcd'), ('far_t.pcd', '/03/target.pcd')):
    pts = read_pcd(root + src)
    with open(name, 'wb') as f:
        f.write(b'VERSION .7\nFIELDS x y z label\nSIZE 8 8 8 4\nTYPE F F F U\nCOUNT 1 1 1 1\n')
        f.write(b'WIDTH %d\nHEIGHT 1\nPOINTS %d\nDATA binary\n' % (len(pts), len(pts)))
        for p in pts: f.write(struct.pack('<3dI', *M(p), p[3]))
T = [list(map(float, l.split())) for l in open(root + '/03/T_target_source.txt') if l.strip()]
R = [[c, -s, 0], [s, c, 0], [0, 0, 1]]; m = [300000.0, 4500000.0, 52.0]
Rt = [[T[i][j] for j in range(3)] for i in range(3)]; t = [T[i][3] for i in range(3)]
mul = lambda A, B: [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
RT = [[R[j][i] for j in range(3)] for i in range(3)]
Rf = mul(mul(R, Rt), RT)  # M T M^-1: R Rt R^T, t' = R t + m - Rf m
Rtm = [sum(Rf[i][k] * m[k] for k in range(3)) for i in range(3)]
tf = [sum(R[i][k] * t[k] for k in range(3)) + m[i] - Rtm[i] for i in range(3)]
with open('far_gt.txt', 'w') as f:
    for i in range(3): f.write('%.17g %.17g %.17g %.17g\n' % (*Rf[i], tf[i]))
    f.write('0 0 0 1\n')
PY
check "11: register a pair 300 km out" "$PAGOR" register --source far_s.pcd --target far_t.pcd --ground-truth far_gt.txt --config "$SEMCFG" --json far.json
grep -q "ground truth: .* SUCCESS" out.log && grep -q "verdict: ACCEPTED" out.log &&
  pass "11: right and accepted, as near the origin" || fail "11: $(grep -E 'ground truth|verdict' out.log)"
python3 -c "
import json; j = json.load(open('far.json'))
T, G = j['T_target_source'], j['ground_truth']['T_target_source']
assert abs(G[1][3] - float(open('far_gt.txt').read().split()[7])) < 1e-6, 'truth not in the file frame'
m = (300000.0, 4500000.0, 52.0)  # near the data, where a right pose maps points as the truth does
at = lambda X: [sum(X[i][k] * m[k] for k in range(3)) + X[i][3] for i in range(3)]
assert sum((a - b) ** 2 for a, b in zip(at(T), at(G))) < 4, 'pose not in the file frame'
" && pass "11: the JSON's poses are in the files' frame" || fail "11: JSON frame"

# ---- 12. a corrupt point fails nothing but itself; a failed pair does not stop the bench ----
python3 -c "
import struct
b = bytearray(open('s20.bin', 'rb').read()); b[160:164] = struct.pack('<f', 1e30)
open('spike.bin', 'wb').write(b)"
printf 'VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 9\nHEIGHT 1\nPOINTS 9\nDATA binary\nxx' >cut.pcd
printf 'spike.bin t30.bin gt=gt.txt source_labels=s20.label target_labels=t30.label name=spike\n' >m12.txt
printf 'cut.pcd t30.bin name=cut\ns20.bin t30.bin gt=gt.txt source_labels=s20.label target_labels=t30.label name=good\n' >>m12.txt
check "12: bench with a spike and a corrupt cloud" "$PAGOR" bench --manifest m12.txt --out r12.jsonl
grep -q "spike.bin: dropped 1 points lying more than 1e6 m" err.log && pass "12: the spike is dropped, naming the file" || fail "12: spike warning"
grep -qE "^spike .* yes .* accept" out.log && grep -qE "^good .* yes .* accept" out.log &&
  pass "12: both good pairs register" || fail "12: rows"
grep -q "^cut  *failed: .*cut.pcd: truncated PCD body" out.log && pass "12: the corrupt pair's row says why" || fail "12: cut row"
[ "$(grep -c run_key r12.jsonl)" -eq 2 ] && pass "12: the results hold the two pairs that ran" || fail "12: results"

# ---- 13. long names, blanks and bytes that are not UTF-8 ----
long=$(printf 'n%.0s' $(seq 1 245)).json  # 250 bytes: with a temporary suffix it passed 255
check "13: register --json to a 250-byte name" "$PAGOR" register --synthetic 7 --json "$long"
[ -s "$long" ] && pass "13: written" || fail "13: not written"
check "13: bench --out to a 250-byte name" "$PAGOR" bench --manifest m2.txt --out "${long%.json}.jsonl"
mkdir -p "my scans" && cp s20.bin "my scans/a scan.bin"
printf '"my scans/a scan.bin" t30.bin gt=gt.txt name="with blanks"\n' >m13.txt
check "13: a manifest path with blanks" "$PAGOR" bench --manifest m13.txt
grep -q "^with blanks .* accept" out.log && pass "13: the pair ran" || fail "13: pair row"
odd="odd_$(printf '\xff\xfe')"
cp s20.bin "$odd.bin" && cp "$SRC/tests/data/association_m100.txt" "$odd.txt"
printf '%s t30.bin gt=gt.txt name=%s\n' "$odd.bin" "$odd" >m13u.txt
check "13: bench --out with a non-UTF-8 path" "$PAGOR" bench --manifest m13u.txt --out u.jsonl
check "13: sweep --out with a non-UTF-8 path" "$PAGOR" sweep --manifest m13u.txt --mu 0.5,1 --out u_sweep.jsonl
check "13: register --correspondences --json with a non-UTF-8 path" "$PAGOR" register --correspondences "$odd.txt" --json u_corr.json
[ -s u.jsonl ] && [ -s u_sweep.jsonl ] && [ -s u_corr.json ] && pass "13: all written" || fail "13: missing output"

echo "$((checks - failures))/$checks checks passed"
[ "$failures" -eq 0 ] && echo PASS || echo FAIL
