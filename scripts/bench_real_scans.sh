#!/usr/bin/env bash
# The persistence benchmark on the inputs users have (issue: persistence speed on
# real scans): pcl_tda_bench_persistence on
#   1. every scan of ../shared/data at full size (finite points) and as random
#      subsamples of 15k and 100k points where the scan is larger, at average vertex
#      degree ~10 and ~20;
#   2. the depth frames (kinect_frame.pcd, the table scene) after a 1 cm voxel grid at
#      radius 2 cm, the setting of the segmentation tool;
#   3. a scaling series at degree ~10 from 10k to 2M points of the table scene
#      (random subsamples up to its 209,280 finite points, jittered copies past it,
#      labelled so in the table).
# Writes doc/benchmarks_real_scans.md (progress goes to stderr) with the scaling
# series drawn as doc/images/persistence_scaling.svg, time against points per tool.
# Usage: scripts/bench_real_scans.sh [build_dir] [runs]   (expects a Release build)
# With 3 runs it takes about 30 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build}/bin
persistence_runs=${2:-3}
out=doc/benchmarks_real_scans.md
picture=doc/images/persistence_scaling.svg
data=../shared/data
rows=$(mktemp -d)
trap 'rm -rf "$rows"' EXIT
source scripts/persistence_bench_functions.sh

# The number of finite points of a scan.
finite_points() {
  "$bin/pcl_tda_bench_persistence" "$1" -find-radius 10 |
    tail -1 | sed 's/.*"points": \([0-9]*\),.*/\1/'
}

# Ripser's point-cloud mode scans all pairs of points: run it where that takes
# seconds (up to 32k points), and at 100k points at degree ~10 (about 30 s a run).
ripser_point_cloud() {
  local points=$1 degree=$2
  [ "$points" -le 32100 ] || { [ "$points" -eq 100000 ] && [ "$degree" -eq 10 ]; }
}

# 1. The corpus.
for input in "$data"/*.pcd; do
  full=$(finite_points "$input")
  sizes=""
  for size in 15000 100000; do
    if [ "$full" -gt "$size" ]; then sizes="$sizes $size"; fi
  done
  for degree in 10 20; do
    for size in $sizes 0; do
      points=$size
      if [ "$size" -eq 0 ]; then points=$full; fi
      tools=ripser-sparse,phat-twist,phat-chunk,cohomology,fip
      if ripser_point_cloud "$points" "$degree"; then tools=$tools,ripser; fi
      radius=$(radius_for_degree "$input" "$degree" -n "$size")
      persistence "corpus$degree" "$input" "$radius" -n "$size" -tools "$tools"
    done
  done
done

# 2. Depth frames after a 1 cm voxel grid, radius 2 cm.
for input in "$data/kinect_frame.pcd" "$data/table_scene_mug_stereo_textured.pcd"; do
  persistence frames "$input" 0.02 -leaf 0.01 -tools all
done

# 3. The scaling series at degree ~10.
table=$data/table_scene_mug_stereo_textured.pcd
for points in 10000 30000 100000 209280 500000 1000000 2000000; do
  tools=fip
  if [ "$points" -le 209280 ]; then tools=ripser-sparse,phat-twist,fip; fi
  if [ "$points" -le 30000 ]; then tools=$tools,ripser; fi
  persistence scaling "$table" "$(radius_for_degree "$table" 10 -n "$points")" \
    -n "$points" -tools "$tools"
done

# The median of a measurement in a JSON line of pcl_tda_bench_persistence, by a
# regular expression that ends just before its "median" (empty when absent).
json_median() {
  sed -n "s/.*$1[^}]*\"median\": \([0-9.e+-]*\).*/\1/p"
}

# The scaling series as an SVG picture: seconds against points, both logarithmic.
draw_scaling() {
  local series
  while read -r line; do
    points=$(sed 's/.*"points": \([0-9]*\),.*/\1/' <<< "$line")
    echo "$points ours_in_process $(json_median '"ours": {"total": {' <<< "$line")"
    echo "$points ours_process $(json_median '"process": {' <<< "$line")"
    echo "$points ripser_sparse $(json_median '"ripser_sparse": {"seconds": {' <<< "$line")"
    echo "$points ripser_point_cloud $(json_median '"ripser": {"seconds": {' <<< "$line")"
    echo "$points phat_twist $(json_median '"twist": {"matrix": {[^}]*}, "reduction": {' \
      <<< "$line")"
  done < "$rows/scaling/json" | awk 'NF == 3' > "$rows/series"
  awk -v title="H0 + H1 persistence, table scene at average degree ~10 ($(nproc) cores)" '
    function lx(x) { return 80 + (log(x) / log(10) - 4) / (log(2e6) / log(10) - 4) * 560 }
    function ly(y) { return 380 - (log(y) / log(10) + 3) / 5 * 320 }
    { x[NR] = $1; tool[NR] = $2; y[NR] = $3 }
    END {
      color["ours_in_process"] = "#1f77b4"; name["ours_in_process"] = "ours, in process"
      color["ours_process"] = "#2ca02c"; name["ours_process"] = "pcl_tda_barcode process"
      color["ripser_sparse"] = "#ff7f0e"; name["ripser_sparse"] = "Ripser sparse, process"
      color["ripser_point_cloud"] = "#d62728"
      name["ripser_point_cloud"] = "Ripser point-cloud, process"
      color["phat_twist"] = "#9467bd"; name["phat_twist"] = "PHAT twist (H1 only)"
      printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"700\" height=\"440\" "
      printf "font-family=\"sans-serif\" font-size=\"12\">\n"
      printf "<rect width=\"700\" height=\"440\" fill=\"white\"/>\n"
      printf "<text x=\"360\" y=\"30\" text-anchor=\"middle\" font-size=\"14\">%s</text>\n", title
      for (e = 4; e <= 6; ++e) for (m = 1; m <= 9; ++m) {
        v = m * 10 ^ e
        if (v > 2e6) break
        printf "<line x1=\"%.1f\" y1=\"60\" x2=\"%.1f\" y2=\"380\" stroke=\"#eee\"/>\n", lx(v), lx(v)
        if (m == 1) printf "<text x=\"%.1f\" y=\"398\" text-anchor=\"middle\">%s</text>\n", lx(v), (e == 4 ? "10k" : e == 5 ? "100k" : "1M")
      }
      for (e = -3; e <= 2; ++e) {
        printf "<line x1=\"80\" y1=\"%.1f\" x2=\"640\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", ly(10 ^ e), ly(10 ^ e)
        printf "<text x=\"74\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n", ly(10 ^ e) + 4, 10 ^ e
      }
      printf "<rect x=\"80\" y=\"60\" width=\"560\" height=\"320\" fill=\"none\" stroke=\"black\"/>\n"
      printf "<text x=\"360\" y=\"425\" text-anchor=\"middle\">points</text>\n"
      printf "<text x=\"20\" y=\"220\" text-anchor=\"middle\" transform=\"rotate(-90 20 220)\">seconds (median)</text>\n"
      split("ours_in_process ours_process ripser_sparse ripser_point_cloud phat_twist", tools)
      legend = 0
      for (k = 1; k <= 5; ++k) {
        t = tools[k]
        path = ""
        for (i = 1; i <= NR; ++i) if (tool[i] == t)
          path = path (path == "" ? "M" : " L") sprintf ("%.1f %.1f", lx(x[i]), ly(y[i]))
        if (path == "") continue
        printf "<path d=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"2\"/>\n", path, color[t]
        for (i = 1; i <= NR; ++i) if (tool[i] == t)
          printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", lx(x[i]), ly(y[i]), color[t]
        ++legend
        printf "<line x1=\"95\" y1=\"%d\" x2=\"115\" y2=\"%d\" stroke=\"%s\" stroke-width=\"2\"/>\n", 60 + 16 * legend, 60 + 16 * legend, color[t]
        printf "<text x=\"120\" y=\"%d\">%s</text>\n", 64 + 16 * legend, name[t]
      }
      printf "</svg>\n"
    }' "$rows/series"
}

draw_scaling > "$picture.tmp"
mv "$picture.tmp" "$picture"

{
  echo "# Persistence on real scans"
  echo
  echo "Generated by \`scripts/bench_real_scans.sh\` on $(date -u +%Y-%m-%d), $(nproc) cores,"
  echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'). Never edited by hand."
  echo
  echo "\`pcl_tda_bench_persistence\` runs ours and the reference tools on the same points"
  echo "in the same run: medians of $persistence_runs runs or more (at least 5 under a"
  echo "second), min-max in brackets; x = reference time / ours. Columns as in"
  echo "benchmarks.md: \"ours s\" is in process (points in memory to diagram), \"ours"
  echo "process s\" is \`pcl_tda_barcode\` from a binary PCD file to a CSV file; Ripser"
  echo "point-cloud is a process reading its text file, compared with our process; Ripser"
  echo "sparse is a process on our edge list, compared with ours in process (divide its"
  echo "time by \"ours process s\" for process against process). Radii by bisection to the"
  echo "average vertex degree (2 edges / points); random subsamples with seed 1."
  echo
  echo "### Every scan, full and subsampled, average degree ~10"
  echo
  rows_of corpus10 end_to_end
  echo
  rows_of corpus10 h1
  echo
  echo "### Every scan, full and subsampled, average degree ~20"
  echo
  rows_of corpus20 end_to_end
  echo
  rows_of corpus20 h1
  echo
  echo "### Depth frames after a 1 cm voxel grid, radius 2 cm"
  echo
  rows_of frames end_to_end
  echo
  rows_of frames h1
  echo
  echo "### Scaling at average degree ~10, table scene (jittered copies past 209,280 points)"
  echo
  echo "![time against points](images/$(basename "$picture"))"
  echo
  rows_of scaling end_to_end
  echo
  rows_of scaling h1
  echo
  echo "Memory: the complex with its triangles listed (16 bytes per edge, 24 per"
  echo "triangle; the default pipeline holds only the edges and enumerates the"
  echo "triangles), the peak resident memory of the pcl_tda_barcode process (about 5 MiB"
  echo 'of it is the process with its libraries loaded, as `pcl_tda_barcode -h` peaks), and'
  echo "what our pipeline added to the benchmark's peak in process."
  echo
  echo "| points | complex MiB | pcl_tda_barcode peak MiB | x complex | in-process growth MiB | x complex |"
  echo "|---|---|---|---|---|---|"
  awk '{
  match($0, /"points": [0-9]+/); points = substr($0, RSTART + 10, RLENGTH - 10)
  match($0, /"complex_bytes": [0-9]+/); complex = substr($0, RSTART + 17, RLENGTH - 17)
  match($0, /"peak_after_loading_bytes": [0-9]+/); loaded = substr($0, RSTART + 28, RLENGTH - 28)
  match($0, /"peak_after_ours_bytes": [0-9]+/); ours = substr($0, RSTART + 24, RLENGTH - 24)
  match($0, /"ours_process_peak_bytes": [0-9]+/); process = substr($0, RSTART + 26, RLENGTH - 26)
  mib = 1048576
  printf "| %d | %.1f | %.1f | %.2f | %.1f | %.2f |\n", points, complex / mib, process / mib,
    process / complex, (ours - loaded) / mib, (ours - loaded) / complex
  }' "$rows/scaling/json"
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "bench_real_scans: wrote $out and $picture" >&2
