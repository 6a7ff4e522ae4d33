#!/usr/bin/env bash
# The main job on generated data: a tabletop scene and a torus, their H0 and H1
# persistence diagrams as CSV, barcodes and persistence diagrams as SVG (the
# tabletop's also as PNG), the
# tabletop scene segmented into objects (labelled PCD and H0 barcode), and the holes
# of a surface found and filled (labelled PCD, table, filled cloud, picture); and the
# viewer's pictures of them.
set -euo pipefail
bin=${1:-build/bin}
out=${2:-out/demo}
mkdir -p "$out"

"$bin/pcl_tda_generate" tabletop "$out/tabletop.pcd" -seed 1
"$bin/pcl_tda_barcode" "$out/tabletop.pcd" "$out/tabletop_diagram.csv" -radius 0.02 \
  -svg "$out/tabletop_barcode.svg" -diagram "$out/tabletop_diagram.svg" -png

# Object segmentation (thesis Sec 4.4): table plane removed by RANSAC, persistent
# Euclidean clustering with the distance chosen from the H0 diagram (up to 10 cm);
# labelled points (one colour per object) and the H0 barcode.
"$bin/pcl_tda_segment" "$out/tabletop.pcd" "$out/tabletop_segments.pcd" -radius 0.1 \
  -auto -min 32 -svg "$out/tabletop_segments_barcode.svg" -png

"$bin/pcl_tda_generate" torus "$out/torus.pcd" -seed 1
"$bin/pcl_tda_barcode" "$out/torus.pcd" "$out/torus_diagram.csv" -radius 0.3 \
  -svg "$out/torus_barcode.svg" -diagram "$out/torus_diagram.svg"

# Hole boundaries (thesis Ch. 5): a bumpy surface with three round holes; its rims
# from minimal 1-cycles, the holes filled on surfaces fitted around them.
"$bin/pcl_tda_generate" holes "$out/holes_surface.pcd" -surface heightfield -seed 1
"$bin/pcl_tda_holes" "$out/holes_surface.pcd" "$out/holes_labels.pcd" \
  -csv "$out/holes.csv" -fill "$out/holes_filled.pcd" -png "$out/holes.png" \
  -svg "$out/holes_h1_barcode.svg"

# The viewer's pictures, rendered off-screen (on a virtual X display where there is
# none): the torus's components and H0/H1 barcode at half the radius, the tabletop's
# objects, the colour regions of a painted scene and the holes with their new points.
if [ -x "$bin/pcl_tda_viewer" ]; then
  viewer=("$bin/pcl_tda_viewer")
  if [ -z "${DISPLAY:-}" ]; then
    viewer=(xvfb-run -a -s "-screen 0 1280x1024x24" "$bin/pcl_tda_viewer")
  fi
  "${viewer[@]}" "$out/torus.pcd" -barcode -radius 0.3 -at 0.15 \
    -screenshot "$out/viewer_torus_barcode.png"
  "${viewer[@]}" "$out/tabletop_segments.pcd" -clusters \
    -screenshot "$out/viewer_tabletop_clusters.png"
  "$bin/pcl_tda_generate" regions "$out/painted.pcd" -seed 1
  "$bin/pcl_tda_regions" "$out/painted.pcd" "$out/painted_regions.pcd"
  "${viewer[@]}" "$out/painted_regions.pcd" -regions \
    -screenshot "$out/viewer_painted_regions.png"
  "${viewer[@]}" "$out/holes_labels.pcd" -holes -fill "$out/holes_filled.pcd" \
    -screenshot "$out/viewer_holes.png"
fi

echo
echo "Demo results in $out:"
for file in "$out"/*; do
  echo "  $file"
done
