#!/usr/bin/env bash
# The main job on generated data: a tabletop scene and a torus, their H0 and H1
# persistence diagrams as CSV, barcodes and persistence diagrams as SVG, the
# tabletop scene segmented into objects (labelled PCD and H0 barcode), and the holes
# of a surface found and filled (labelled PCD, table, filled cloud, picture).
set -euo pipefail
bin=${1:-build/bin}
out=${2:-out/demo}
mkdir -p "$out"

"$bin/pcl_tda_generate" tabletop "$out/tabletop.pcd" -seed 1
"$bin/pcl_tda_barcode" "$out/tabletop.pcd" "$out/tabletop_diagram.csv" -radius 0.02 \
  -svg "$out/tabletop_barcode.svg" -diagram "$out/tabletop_diagram.svg"

# Object segmentation (thesis Sec 4.4): table plane removed by RANSAC, persistent
# Euclidean clustering with the distance chosen from the H0 diagram (up to 10 cm);
# labelled points (one colour per object) and the H0 barcode.
"$bin/pcl_tda_segment" "$out/tabletop.pcd" "$out/tabletop_segments.pcd" -radius 0.1 \
  -auto -min 32 -svg "$out/tabletop_segments_barcode.svg"

"$bin/pcl_tda_generate" torus "$out/torus.pcd" -seed 1
"$bin/pcl_tda_barcode" "$out/torus.pcd" "$out/torus_diagram.csv" -radius 0.3 \
  -svg "$out/torus_barcode.svg" -diagram "$out/torus_diagram.svg"

# Hole boundaries (thesis Ch. 5): a bumpy surface with three round holes; its rims
# from minimal 1-cycles, the holes filled on surfaces fitted around them.
"$bin/pcl_tda_generate" holes "$out/holes_surface.pcd" -surface heightfield -seed 1
"$bin/pcl_tda_holes" "$out/holes_surface.pcd" "$out/holes_labels.pcd" \
  -csv "$out/holes.csv" -fill "$out/holes_filled.pcd" -png "$out/holes.png" \
  -svg "$out/holes_h1_barcode.svg"

echo
echo "Demo results in $out:"
for file in "$out"/*; do
  echo "  $file"
done
