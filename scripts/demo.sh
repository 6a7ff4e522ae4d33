#!/usr/bin/env bash
# The main job on generated data: a tabletop scene and a torus, their H0 and H1
# persistence diagrams as CSV, barcodes and persistence diagrams as SVG.
set -euo pipefail
bin=${1:-build/bin}
out=${2:-out/demo}
mkdir -p "$out"

"$bin/pcl_tda_generate" tabletop "$out/tabletop.pcd" -seed 1
"$bin/pcl_tda_barcode" "$out/tabletop.pcd" "$out/tabletop_diagram.csv" -radius 0.02 \
  -svg "$out/tabletop_barcode.svg" -diagram "$out/tabletop_diagram.svg"

"$bin/pcl_tda_generate" torus "$out/torus.pcd" -seed 1
"$bin/pcl_tda_barcode" "$out/torus.pcd" "$out/torus_diagram.csv" -radius 0.3 \
  -svg "$out/torus_barcode.svg" -diagram "$out/torus_diagram.svg"

echo
echo "Demo results in $out:"
for file in "$out"/*; do
  echo "  $file"
done
