#!/usr/bin/env bash
# The bad-input suite: every reproducer in ../shared/data/bad-inputs (but the studio's session_*
# files) and the generated cases, through the CLI entry points. Each must end with exit code 1 and
# exactly one line on stderr, "pagor: error: ...", naming the file (and key or line).
# usage: bad_inputs.sh PAGOR BAD_INPUTS_DIR KITTI_ROOT WORK_DIR
set -u
PAGOR=$1 BAD=$2 KITTI=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK"
failures=0 checks=0

# expect_error "needle1|needle2|..." command args...: exit 1, one stderr line containing each needle.
expect_error() {
  local needles=$1
  shift
  checks=$((checks + 1))
  local err="$WORK/stderr" code
  timeout 300 "$@" >/dev/null 2>"$err"
  code=$?
  local lines
  lines=$(wc -l <"$err")
  local ok=1
  [ "$code" -eq 1 ] || ok=0
  [ "$lines" -eq 1 ] || ok=0
  grep -q '^pagor: error: ' "$err" || ok=0
  local IFS='|'
  for n in $needles; do grep -qF -- "$n" "$err" || ok=0; done
  if [ $ok -eq 1 ]; then
    echo "ok    $*"
  else
    failures=$((failures + 1))
    echo "FAIL  $*   (exit $code, $lines stderr lines; wanted: $needles)"
    head -c 2000 "$err" | sed 's/^/      | /'
  fi
}

# Clouds: landmarks and register (as source and as target).
for f in "$BAD"/pcd_*.pcd "$BAD"/ply_*.ply; do
  name=$(basename "$f")
  expect_error "$name" "$PAGOR" landmarks --source "$f"
  expect_error "$name" "$PAGOR" register --source "$f" --target "$KITTI/sequences/00/velodyne/000000.bin"
  expect_error "$name" "$PAGOR" register --source "$KITTI/sequences/00/velodyne/000000.bin" --target "$f"
done

# Configs that are invalid as written: config --check, and every command that takes --config.
declare -A key=(
  [cfg_maxcorr_2p32_becomes_0.json]="correspondences.max_correspondences"
  [cfg_maxcorr_1e10_truncated.json]="correspondences.max_correspondences"
  [cfg_seed_negfloat_ub.json]="clique.seed"
  [cfg_float_to_int_ub.json]="correspondences.max_correspondences"
  [cfg_1e400_internal_error.json]="1e400"
  [cfg_verif_voxel_1e-300.json]="verification.voxel_size"
)
for name in "${!key[@]}"; do
  f="$BAD/$name"
  expect_error "$name|${key[$name]}" "$PAGOR" config --check "$f"
  expect_error "$name|${key[$name]}" "$PAGOR" register --synthetic 7 --config "$f"
  expect_error "$name|${key[$name]}" "$PAGOR" landmarks --synthetic 7 --config "$f"
  expect_error "$name|${key[$name]}" "$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$f"
done

# Absurd configs: out of the field's range, or bounded by a work budget derived from the input,
# with the key named.
expect_error "cfg_huge_tolerance_hang.json: landmarks.classes[0].cluster_tolerance|is outside (0, 50]" \
  "$PAGOR" register --kitti-root "$KITTI" --pair 0 20 --config "$BAD/cfg_huge_tolerance_hang.json"
expect_error "cfg_huge_tolerance_hang.json: landmarks.classes[0].cluster_tolerance|is outside (0, 50]" \
  "$PAGOR" landmarks --kitti-root "$KITTI" --frame 0 --config "$BAD/cfg_huge_tolerance_hang.json"
expect_error "cfg_nocap_many_landmarks_mem.json: |budget" \
  "$PAGOR" register --kitti-root "$KITTI" --pair 0 20 --config "$BAD/cfg_nocap_many_landmarks_mem.json"
expect_error "cfg_nocap_many_landmarks_mem.json: |budget" \
  "$PAGOR" bench --kitti-root "$KITTI" --pairs "$KITTI/pairs_00_dev.txt" --config "$BAD/cfg_nocap_many_landmarks_mem.json"

# Pairs files.
expect_error "pairs_frac_silent.txt:1|'20.5' is not a frame number" \
  "$PAGOR" bench --kitti-root "$KITTI" --pairs "$BAD/pairs_frac_silent.txt"
expect_error "pairs_exp_misleading.txt:1|'1e3' is not a frame number" \
  "$PAGOR" bench --kitti-root "$KITTI" --pairs "$BAD/pairs_exp_misleading.txt"

# Generated: 100000-deep nesting in a config.
deep="$WORK/deep.json"
{ printf '{"graph": {"trim": '; head -c 100000 /dev/zero | tr '\0' '['; head -c 100000 /dev/zero | tr '\0' ']'; printf '}}'; } >"$deep"
expect_error "deep.json|nesting deeper than 64" "$PAGOR" config --check "$deep"
expect_error "deep.json|nesting deeper than 64" "$PAGOR" register --synthetic 7 --config "$deep"

# Generated: KITTI sequences whose poses.txt or calib.txt Tr is all zeros.
make_seq() {  # make_seq DIR: a sequence sharing the real scans, with copies of poses and calib
  mkdir -p "$1/sequences/00"
  ln -s "$(cd "$KITTI/sequences/00" && pwd)/velodyne" "$1/sequences/00/velodyne"
  ln -s "$(cd "$KITTI/sequences/00" && pwd)/labels" "$1/sequences/00/labels"
  cp "$KITTI/sequences/00/poses.txt" "$KITTI/sequences/00/calib.txt" "$1/sequences/00/"
  chmod u+w "$1/sequences/00/poses.txt" "$1/sequences/00/calib.txt"
}
zeros="0 0 0 0 0 0 0 0 0 0 0 0"
make_seq "$WORK/zero_pose"
sed -i "21s/.*/$zeros/" "$WORK/zero_pose/sequences/00/poses.txt"
expect_error "poses.txt:21|not a rigid transform" "$PAGOR" register --kitti-root "$WORK/zero_pose" --pair 0 20
expect_error "poses.txt:21|not a rigid transform" "$PAGOR" bench --kitti-root "$WORK/zero_pose" --pairs "$KITTI/pairs_00_dev.txt"
expect_error "poses.txt:21|not a rigid transform" "$PAGOR" landmarks --kitti-root "$WORK/zero_pose" --frame 0
make_seq "$WORK/zero_tr"
sed -i "s/^Tr:.*/Tr: $zeros/" "$WORK/zero_tr/sequences/00/calib.txt"
expect_error "calib.txt:|Tr is not a rigid transform" "$PAGOR" register --kitti-root "$WORK/zero_tr" --pair 0 20

# Generated: a cloud whose path is not UTF-8, with --json: the result is written (the path is
# stored with U+FFFD), exit 0.
checks=$((checks + 1))
odd="$WORK/scan_$(printf '\xff\xfe').bin"
cp "$KITTI/sequences/00/velodyne/000000.bin" "$odd"
if "$PAGOR" landmarks --source "$odd" --source-labels "$KITTI/sequences/00/labels/000000.label" \
    --json "$WORK/odd.json" >/dev/null 2>"$WORK/stderr" && grep -q '"landmarks"' "$WORK/odd.json"; then
  echo "ok    non-UTF-8 path with landmarks --json"
else
  failures=$((failures + 1))
  echo "FAIL  non-UTF-8 path with landmarks --json"
  sed 's/^/      | /' "$WORK/stderr"
fi

echo "$((checks - failures))/$checks checks passed"
[ "$failures" -eq 0 ]
