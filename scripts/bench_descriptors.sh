#!/usr/bin/env bash
# The descriptor benchmark (thesis Table 6.1 and Experiments 2-3 analogue): STPP,
# its Betti-0 and Betti-1 parts, the topological covariance descriptor and PCL's
# VFH, ESF, GRSD, CVFH and OUR-CVFH on the same generated views
# (pcl_tda_generate shapes), classified by pcl_tda_classify with the same splits:
#   1. every descriptor at the camera's noise and at 3x the noise;
#   2. thesis Experiment 3: every point moved by a uniform amount in [-A, A] per
#      coordinate, A = 0.5, 1 and 3 mm, for STPP and ESF.
# Prints markdown tables (accuracy mean +- sd over the trials, time per view,
# normals included) to stdout; progress goes to stderr.
# Usage: scripts/bench_descriptors.sh [build_dir] [instances] [views] [trials]
# With the defaults (4 instances, 12 views, 10 trials) it takes about 40 minutes on
# 2 cores; 4 4 5 takes about 8.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build}/bin
instances=${2:-4}
views=${3:-12}
trials=${4:-10}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

all=stpp,stpp0,stpp1,covariance,vfh,esf,grsd,cvfh,ourcvfh,stpp+vfh,stpp+esf

# classify NAME DESCRIPTORS GENERATE-OPTIONS...: generates a data set and writes the
# classification's CSV to $work/NAME.csv.
classify() {
  local name=$1 descriptors=$2
  shift 2
  echo "bench_descriptors: $name" >&2
  "$bin/pcl_tda_generate" shapes "$work/$name" -instances "$instances" \
    -views "$views" "$@" > /dev/null
  "$bin/pcl_tda_classify" "$work/$name/manifest.csv" -descriptors "$descriptors" \
    -trials "$trials" -csv "$work/$name.csv" > /dev/null
}

# accuracy NAME DESCRIPTOR: "mean +- sd" in percent from $work/NAME.csv.
accuracy() {
  awk -F, -v d="$2" 'NR > 1 && $1 == d {
    printf "%.1f +- %.1f", 100 * $6, 100 * $7 }' "$work/$1.csv"
}

# column NAME DESCRIPTOR FIELD: a field of a descriptor's row.
column() {
  awk -F, -v d="$2" -v f="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i }
    NR > 1 && $1 == d { print $(c[f]) }' "$work/$1.csv"
}

classify noise1 "$all" -noise 1
classify noise3 "$all" -noise 3
for a in 0.0005 0.001 0.003; do
  classify "perturb$a" stpp,esf -perturb "$a"
done

echo "### Accuracy and time per view, $instances instances x $views views of 12 categories, $trials trials"
echo
echo "| descriptor | values | accuracy (%), camera noise | accuracy (%), 3x noise | drop | ms per view (median) |"
echo "|---|---|---|---|---|---|"
for d in ${all//,/ }; do
  a1=$(column noise1 "$d" accuracy_mean)
  a3=$(column noise3 "$d" accuracy_mean)
  drop=$(awk -v a="$a1" -v b="$a3" 'BEGIN { printf "%.1f", 100 * (a - b) }')
  printf '| %s | %s | %s | %s | %s | %.1f |\n' "$d" "$(column noise1 "$d" dimension)" \
    "$(accuracy noise1 "$d")" "$(accuracy noise3 "$d")" "$drop" \
    "$(column noise1 "$d" ms_per_view_median)"
done
echo
echo "### Thesis Experiment 3: every coordinate moved by a uniform amount in [-A, A]"
echo
echo "| descriptor | A = 0 | A = 0.5 mm | A = 1 mm | A = 3 mm |"
echo "|---|---|---|---|---|"
for d in stpp esf; do
  printf '| %s | %s | %s | %s | %s |\n' "$d" "$(accuracy noise1 "$d")" \
    "$(accuracy perturb0.0005 "$d")" "$(accuracy perturb0.001 "$d")" \
    "$(accuracy perturb0.003 "$d")"
done
