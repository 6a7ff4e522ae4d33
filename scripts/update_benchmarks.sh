#!/usr/bin/env bash
# Regenerates doc/benchmarks.md from the benchmarks, run on this machine now.
# Usage: scripts/update_benchmarks.sh [build_dir] [section ...]   (a Release build)
# With no section, every section is measured and the document written anew (about
# two hours on 2 cores). With sections, only those are measured again and replace
# their part of the document; each section says when it was measured. Sections:
#   barcode (about 1 minute), persistence (about 25), incremental (about 5),
#   real_scans (about 35; also writes doc/benchmarks_real_scans.md), clustering,
#   regions, holes, descriptors (about 20).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build}/bin
all_sections="barcode persistence incremental real_scans clustering regions holes descriptors"
sections=("${@:2}")
for section in "${sections[@]}"; do
  case " $all_sections " in
    *" $section "*) ;;
    *)
      echo "update_benchmarks: unknown section '$section' (sections: $all_sections)" >&2
      exit 1
      ;;
  esac
done
data=../shared/data
out=doc/benchmarks.md
runs=5
# pcl_tda_bench_persistence runs each measurement this often, and at least 5 times
# when it takes under a second.
persistence_runs=3
rows=$(mktemp -d)
trap 'rm -rf "$rows" "$out.tmp" "$out.tmp.new"' EXIT

table() {
  # One benchmark row per call; keep the header of the first.
  "$bin/pcl_tda_bench_barcode" "$@" "$runs" | grep '^|' | sed '1d'
}

# radius_for_degree, persistence and rows_of.
source scripts/persistence_bench_functions.sh

# The line under a section's title: when it was measured.
measured() {
  echo
  echo "Measured on $(date -u +%Y-%m-%d) by \`scripts/update_benchmarks.sh\`."
}

section_barcode() {
  echo "## pcl_tda_barcode vs Ripser (point-cloud mode), H0 + H1"
  measured
  echo
  echo "Ours: \`pcl_tda_barcode in.pcd out.csv -radius R\` (grid neighbour search, parallel"
  echo "Vietoris-Rips build of the edges, union-find H0, cohomology H1 with the triangles"
  echo "enumerated, not listed). Ripser:"
  echo "\`ripser --format point-cloud --dim 1 --threshold R\` on the same points. The"
  echo "diagrams are compared as multisets with relative tolerance 1e-5. Times are"
  echo "medians of $runs runs (min-max in brackets), wall clock, end to end (file in,"
  echo "diagram out)."
  echo
  echo "| input | points | radius | runs | pcl_tda_barcode s (min-max) | ripser s (min-max) | speed-up | diagrams |"
  echo "|---|---|---|---|---|---|---|---|"
  table "$data/bunny.pcd" 0.02
  table "$data/milk.pcd" 0.005
  table "$data/rops_cloud.pcd" 0.0045
  table "$data/rops_cloud.pcd" 0.006
}

section_persistence() {
  # Thesis Table 3.1 analogue: random subsamples of one scan, 60k and 100k points by
  # jittered copies, at average vertex degrees ~10 and ~20. GUDHI and all of PHAT's
  # reductions are left out where they would take minutes (degree 20 from 60k points).
  rops=$data/rops_cloud.pcd
  for degree in 10 20; do
    for points in 15000 30000 60000 100000; do
      tools=all
      if [ "$degree" -eq 20 ] && [ "$points" -gt 30000 ]; then
        tools=ripser,ripser-sparse,phat-twist,incremental,fip
      fi
      radius=$(radius_for_degree "$rops" "$degree" -n "$points")
      persistence scaling "$rops" "$radius" -n "$points" -tools "$tools"
    done
  done
  echo "## Persistence vs Ripser, GUDHI and PHAT (thesis Table 3.1 analogue)"
  measured
  echo
  echo "\`pcl_tda_bench_persistence\` on random subsamples of \`rops_cloud.pcd\` (32,087"
  echo "points; 60k and 100k points are drawn from copies jittered by Gaussian noise of"
  echo "1e-4 of the bounding box diagonal), at the radii where the average vertex degree"
  echo "(2 edges / points) is ~10 and ~20, found by bisection (\`-find-radius\`). Seconds,"
  echo "medians of $persistence_runs runs or more (at least 5 under a second), min-max in"
  echo "brackets; x = reference time / ours, above 1 when ours is faster."
  echo
  echo "- ours: in process, point cloud in memory to H0 + H1 diagram: Vietoris-Rips build"
  echo "  of the edges ($(nproc) OpenMP threads), union-find H0, cohomology H1 with the"
  echo "  triangles enumerated, not listed (the default, as pcl_tda_barcode runs it)."
  echo "- ours process: \`pcl_tda_barcode\` from PCD file to CSV file, compared with"
  echo "  Ripser's process: \`ripser --format point-cloud --dim 1 --threshold R\`."
  echo "- Ripser sparse: \`ripser --format sparse\` on our edge list, compared with ours in"
  echo "  process; its time leaves out building the edges, ours includes it."
  echo "- GUDHI 3.7.1: \`Rips_complex\` into a \`Simplex_tree\` of dimension 2 +"
  echo "  \`Persistent_cohomology\` over Z2, in process; compared with ours in process."
  echo "- diagrams: all compared with ours as multisets, relative tolerance 1e-5."
  echo
  rows_of scaling end_to_end
  echo
  echo "H1 alone on the very same complex: our default H1 (triangles enumerated), our"
  echo "engines on the complex with its triangles listed (H1 given H0; the standard engine"
  echo "recomputes H0 too) and PHAT 1.6's reductions of our boundary matrix"
  echo "(\`bit_tree_pivot_column\`; matrix construction timed apart; chunk with $(nproc)"
  echo "OpenMP threads, spectral_sequence with 1, the others are serial). Medians; x ="
  echo "time / our default H1. pairs: whether PHAT's persistence pairs equal our"
  echo "cohomology engine's exactly and every engine's diagram equals the default's."
  echo
  rows_of scaling h1
}

section_incremental() {
  # Thesis Tables 5.1-5.4 analogue: incremental vs fast incremental persistence on real
  # scans, raw at average degree ~20 (Table 5.4: raw clouds, many triangles), then after
  # a voxel grid with radius 1.5 leaves (Tables 5.1-5.3: 2 mm grid, 3 mm radius). Leaves
  # follow each scan's point spacing; 1 cm for the table scene as in PCL's tutorials.
  for scan in milk:0.004 car6:0.2 rops_cloud:0.004 table_scene_mug_stereo_textured:0.01; do
    input=$data/${scan%%:*}.pcd
    leaf=${scan##*:}
    persistence scans "$input" "$(radius_for_degree "$input" 20)" -tools incremental,fip
    persistence scans "$input" "$(awk -v leaf="$leaf" 'BEGIN { print 1.5 * leaf }')" \
      -leaf "$leaf" -tools incremental,fip
  done
  echo "## Incremental vs fast incremental persistence (thesis Tables 5.1-5.4 analogue)"
  measured
  echo
  echo "H1 given H0 on real scans by the incremental engine (Alg 5.11) and the fast"
  echo "incremental one (Alg 5.12-5.14): raw (non-finite points dropped) at the radius of"
  echo "average degree ~20, and after a voxel grid of leaf L at radius 1.5 L. beta1:"
  echo "essential H1 classes at that radius. Medians, min-max in brackets."
  echo
  rows_of scans incremental
}

section_real_scans() {
  echo "## Persistence on real scans: the corpus"
  measured
  echo
  echo "In [benchmarks_real_scans.md](benchmarks_real_scans.md), written by"
  echo "\`scripts/bench_real_scans.sh\` in this run: \`pcl_tda_bench_persistence\` on every"
  echo "scan of ../shared/data at full size and as random subsamples, on the depth frames"
  echo "after a voxel grid, and a scaling series to 2M points with its picture. See"
  echo "doc/performance.md for where the time goes."
  scripts/bench_real_scans.sh "${1:-build}" "$persistence_runs" || {
    echo "update_benchmarks: failed: bench_real_scans.sh" >&2
    exit 1
  }
}

section_clustering() {
  echo "## PersistentEuclideanClusterExtraction vs pcl::EuclideanClusterExtraction"
  measured
  echo
  echo "\`pcl_tda_bench_clustering\`: our extract (grid, full H0 diagram; $(nproc) OpenMP"
  echo "threads, and 1) against PCL's (k-d tree built inside extract(), serial) on the"
  echo "same cloud with the same tolerance and size limits; medians of 7 runs after a"
  echo "warm-up, min-max in brackets. Clusters compared with our PCL distance test"
  echo "option (identical required) and with our default test (length <= tolerance)."
  echo "Then thesis Table 4.1's columns for generated tabletop scenes, plane removed."
  echo
  clustering_status=0
  clustering=$("$bin/pcl_tda_bench_clustering" "$data") || clustering_status=$?
  if [ "$clustering_status" -eq 2 ]; then
    echo "update_benchmarks: clusters differ from PCL's" >&2
  elif [ "$clustering_status" -ne 0 ]; then
    echo "update_benchmarks: failed: pcl_tda_bench_clustering" >&2
    exit 1
  fi
  printf '%s\n' "$clustering" | sed '$d'
}

section_regions() {
  echo "## PersistentRegionGrowingRGB vs pcl::RegionGrowingRGB and pcl::RegionGrowing"
  measured
  echo
  echo "\`pcl_tda_bench_regions -scenes 6 -runs 3\`: \`pcl_tda_regions\` with no options (one"
  echo "setting for every noise level; spacing, normals and radius graph in its time)"
  echo "against \`pcl::RegionGrowingRGB\` (defaults, the PCL tutorial's settings, and the"
  echo "best of 40 settings chosen per noise level) and \`pcl::RegionGrowing\` (the"
  echo "tutorial's settings) on the same generated scenes (\`pcl_tda_generate regions\`);"
  echo "ARI: adjusted Rand index over all points; correct, over, under: Hoover's counts"
  echo "at T = 0.8. Then frames of the held-out depth camera generator and the real"
  echo "coloured scans. See doc/persistent_region_growing_rgb.md."
  echo
  regions=$("$bin/pcl_tda_bench_regions" "$data" -scenes 6 -runs 3) || {
    echo "update_benchmarks: failed: pcl_tda_bench_regions" >&2
    exit 1
  }
  printf '%s\n' "$regions" | sed '$d'
}

section_holes() {
  echo "## HoleBoundaryEstimation vs pcl::BoundaryEstimation"
  measured
  echo
  echo "\`pcl_tda_bench_holes -scenes 4 -runs 3\`: \`pcl::tda::HoleBoundaryEstimation\` at its"
  echo "defaults (radius and rim band from the surface spacing) against"
  echo "\`pcl::NormalEstimationOMP\` + \`pcl::BoundaryEstimation\` (the usual tutorial"
  echo "settings, and the best of 75 settings of normal radius, boundary radius and angle"
  echo "chosen per surface kind and noise level) on the same generated hole surfaces"
  echo "(\`pcl_tda_generate holes\`: plane, height field, cylinder, sphere, torus; noise 0,"
  echo "0.1, 0.25 h): per-point precision, recall and F1 of the rim band (outer border"
  echo "left out), hole-level recall and precision of our rims, and time. Then thesis"
  echo "Sec 5.6 (Tables 5.1-5.3 analogue) on the real scans with 10-30 % of the points"
  echo "removed at random. Filling (\`HoleFilling\`, surface mode) of the holes found:"
  echo "against the samples the generated holes cut out, and on the real scans against"
  echo "the points removed."
  echo
  holes=$("$bin/pcl_tda_bench_holes" "$data" -scenes 4 -runs 3) || {
    echo "update_benchmarks: failed: pcl_tda_bench_holes" >&2
    exit 1
  }
  # Its own "##" title and the blank line after it, and the JSON line, left out.
  printf '%s\n' "$holes" | sed '1,2d;$d'
  echo
  echo "### Real scans with round holes cut in (data not made by our generator)"
  echo
  echo "\`pcl_tda_bench_holes_cut -seeds 3 -holes 3\`: holes of radius R = 4 h and 8 h (h: the"
  echo "scan's surface spacing) cut around random points well inside each scan (their"
  echo "2R-neighbourhood holds at least 90 % of the median number of points, and the points"
  echo "at R to 2R leave no angular gap around the centre wider than 45 degrees: a hole, not"
  echo "a notch at a border), at least 4R apart; ours at its defaults. Centred: a rim's"
  echo "centroid lies within R / 2 of the hole's centre (the criterion of the generated"
  echo "holes above). Around: a rim passes within 1.5 R of the centre and holds it inside,"
  echo "in the rim's plane (the cut hole joined a larger empty region of the scan). Rims"
  echo "reported: all rims, the scans' own holes and gaps included (not scored). Time:"
  echo "median over the seeds. Filling: \`HoleFilling\` (surface mode) in the holes ours"
  echo "found; new points in the cut holes: those within R + h of a cut centre; to removed:"
  echo "the median distance from such a point to the nearest point the cut removed (the"
  echo "true surface), in h; removed covered: the removed points with a new point within"
  echo "1.5 h (holes not found count as not covered)."
  echo
  "$bin/pcl_tda_bench_holes_cut" "$data" -seeds 3 -holes 3 || {
    echo "update_benchmarks: failed: pcl_tda_bench_holes_cut" >&2
    exit 1
  }
}

section_descriptors() {
  echo "## STPP and the covariance descriptor vs PCL's global descriptors"
  measured
  echo
  echo "\`scripts/bench_descriptors.sh\`: \`pcl_tda_generate shapes\` views (12 categories,"
  echo "4 instances, 12 views each) classified by \`pcl_tda_classify\` (one instance per"
  echo "category held out per trial, RBF SVM, C and gamma by cross-validation over the"
  echo "training instances, values scaled to [0, 1]; the same splits for every"
  echo "descriptor), at the camera's noise and at 3x; then thesis Experiment 3. See"
  echo "doc/classification.md."
  echo
  scripts/bench_descriptors.sh "${1:-build}" 4 12 5 || {
    echo "update_benchmarks: failed: bench_descriptors.sh" >&2
    exit 1
  }
}

document_header() {
  echo "# Measured benchmarks"
  echo
  echo "Written by \`scripts/update_benchmarks.sh\` on $(nproc) cores,"
  echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); each section"
  echo "says when it was measured. Every row runs our tool and the reference tool on the"
  echo "same input in the same run. Never edited by hand."
}

# replace_section NEW DOC: replaces in DOC the section whose "## " title is the first
# line of NEW, up to the next title, by NEW; appends NEW when DOC has no such section.
replace_section() {
  awk -v new="$1" '
    function emit(  line) {
      while ((getline line < new) > 0)
        print line
      close(new)
      done = 1
    }
    BEGIN { getline title < new; close(new) }
    /^## / && skipping { skipping = 0; print "" }
    $0 == title { emit(); skipping = 1; next }
    !skipping { print }
    END { if (!done) { print ""; emit() } }' "$2" > "$2.new"
  mv "$2.new" "$2"
}

if [ "${#sections[@]}" -eq 0 ]; then
  {
    document_header
    for section in $all_sections; do
      echo
      "section_$section"
    done
  } > "$out.tmp"
else
  if [ ! -f "$out" ]; then
    echo "update_benchmarks: $out does not exist: run every section first" >&2
    exit 1
  fi
  cp "$out" "$out.tmp"
  for section in "${sections[@]}"; do
    "section_$section" > "$rows/$section.md"
    replace_section "$rows/$section.md" "$out.tmp"
  done
fi
mv "$out.tmp" "$out"
echo "wrote $out"
