#!/usr/bin/env bash
# Ablation of the real-data changes on every shared set: each change alone on top of the paper's
# configuration, and each change removed from the defaults. Prints one row per setting and set:
# success of the selected pose, the upper bound (any level), the verdict's precision and recall.
# Usage: bench/ablation_real_data.sh [build/app/pagor]
set -euo pipefail
cd "$(dirname "$0")/.."
PAGOR=${1:-build/app/pagor}
SHARED=../shared/data
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

declare -A settings=(
  ["paper"]='"preset":"paper"'
  ["paper + spacing"]='"preset":"paper","landmarks":{"adapt_to_spacing":true}'
  ["paper + structure keypoints"]='"preset":"paper","landmarks":{"fallback":{"mode":"automatic"}}'
  ["paper + 4-DoF"]='"preset":"paper","gnc":{"model":"four_dof"}'
  ["default - spacing"]='"landmarks":{"adapt_to_spacing":false}'
  ["default - structure keypoints"]='"landmarks":{"fallback":{"mode":"never"}}'
  ["default - 4-DoF (SE(3))"]='"gnc":{"model":"se3"}'
  ["default - refinement"]='"refinement":{"enabled":false}'
  ["default"]=''
)
order=("paper" "paper + spacing" "paper + structure keypoints" "paper + 4-DoF"
       "default - spacing" "default - structure keypoints" "default - 4-DoF (SE(3))"
       "default - refinement" "default")

printf '%-32s %-10s %-9s %-9s %-10s %-8s %s\n' setting set success bound precision recall "failed pairs"
for name in "${order[@]}"; do
  for set in semreg-dev kitti; do
    if [ "$set" = semreg-dev ]; then
      [ -d "$SHARED/semreg-dev" ] || continue
      echo "{\"label_scheme\":\"semantickitti-learning\"${settings[$name]:+,${settings[$name]}}}" > "$tmp/c.json"
      args=(--manifest bench/manifests/semreg-dev.txt)
    else
      [ -d "$SHARED/kitti" ] || continue
      echo "{${settings[$name]}}" > "$tmp/c.json"
      args=(--kitti-root "$SHARED/kitti" --pairs "$SHARED/kitti/pairs_00_dev.txt")
    fi
    out=$("$PAGOR" bench "${args[@]}" --config "$tmp/c.json" 2>/dev/null)
    success=$(sed -n 's/^success.*: \([0-9]*\/[0-9]*\) .*/\1/p' <<<"$out")
    bound=$(sed -n 's/^upper bound[^:]*: *\([0-9]*\/[0-9]*\) .*/\1/p' <<<"$out")
    precision=$(sed -n 's/^verdict: .*precision \([0-9.]* %\).*/\1/p' <<<"$out")
    recall=$(sed -n 's/^verdict: .*recall \([0-9.]* %\).*/\1/p' <<<"$out")
    failed=$(awk 'NR > 1 && $5 == "no" { printf "%s ", $1 } /^$/ { exit }' <<<"$out")
    printf '%-32s %-10s %-9s %-9s %-10s %-8s %s\n' "$name" "$set" "$success" "$bound" "$precision" \
      "$recall" "${failed:--}"
  done
done
