#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time with its seed corpus (the committed seeds in
# fuzz/corpus/<target> plus the matching files of ../shared/data), and prints its final stats.
# usage: fuzz/run.sh BUILD_DIR TARGET SECONDS
#   (TARGET: pcd ply lzf config kitti_text floor_plan manifest correspondences session)
# BUILD_DIR must be configured with clang and -DPAGOR_FUZZ=ON -DPAGOR_SANITIZE=ON (see README).
# Exit status is non-zero when the fuzzer found a crash, a leak, a timeout or an out-of-memory;
# the input is then in BUILD_DIR/fuzz-artifacts/.
set -euo pipefail
build=$1 target=$2 seconds=$3
here=$(cd "$(dirname "$0")" && pwd)
shared="$here/../../shared/data"
corpus="$build/fuzz-corpus/$target"
artifacts="$build/fuzz-artifacts/$target"
mkdir -p "$corpus" "$artifacts"
cp -n "$here/corpus/$target"/* "$corpus/" 2>/dev/null || true
if [ -d "$shared" ]; then
  case $target in
    pcd) cp -n "$shared"/bad-inputs/*.pcd "$corpus/" 2>/dev/null || true
         # One real cloud, cut to its header and first 64 points (the fuzzer explores the rest).
         f="$shared/semreg-dev/03/source.pcd"
         [ -f "$f" ] && head -c $((153 + 64 * 16)) "$f" >"$corpus/semreg-03-head.pcd" ;;
    correspondences)  # the first 40 lines of two learned-matcher problems
      for f in "$shared"/gedi-dev/03.txt "$shared"/gedi-dev/08.txt; do
        [ -f "$f" ] && head -n 40 "$f" >"$corpus/gedi-$(basename "$f")"
      done ;;
    ply) cp -n "$shared"/bad-inputs/*.ply "$corpus/" 2>/dev/null || true ;;
    config) cp -n "$shared"/bad-inputs/cfg_*.json "$corpus/" 2>/dev/null || true ;;
    session) cp -n "$shared"/bad-inputs/session_*.json "$here"/../tests/studio/*.json "$corpus/" \
               2>/dev/null || true ;;
    floor_plan) cp -n "$here"/../tests/data/indoor/plan.json "$here"/../tests/data/bad_plan.json \
                  "$corpus/" 2>/dev/null || true ;;
    manifest)
      for f in "$here"/../bench/manifests/*.txt "$shared"/kitti/pairs_*.txt; do
        [ -f "$f" ] && { printf '\000'; cat "$f"; } >"$corpus/$(basename "$f")"
      done ;;
    kitti_text)
      for f in "$shared"/bad-inputs/pairs_*.txt "$shared"/kitti/pairs_*.txt; do
        [ -f "$f" ] && { printf '\000'; cat "$f"; } >"$corpus/$(basename "$f")"
      done
      p="$shared/kitti/sequences/00/poses.txt"
      [ -f "$p" ] && { printf '\001'; head -n 40 "$p"; } >"$corpus/poses-00"
      c="$shared/kitti/sequences/00/calib.txt"
      [ -f "$c" ] && { printf '\002'; cat "$c"; } >"$corpus/calib-00" ;;
  esac
fi
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
"$build/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -malloc_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" 2>&1 |
  grep -E "^(#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY|.*runtime error|Done [0-9]+ runs)|INFO: seed corpus" || true
# libFuzzer leaves crash-*, leak-*, timeout-* or oom-* files when it finds something.
if ls "$artifacts" | grep -qE '^(crash|leak|timeout|oom|slow-unit)-'; then
  echo "fuzz_$target: FINDINGS in $artifacts"; exit 1
fi
echo "fuzz_$target: no findings in $seconds s"
