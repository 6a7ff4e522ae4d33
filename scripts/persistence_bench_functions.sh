# Functions of the persistence benchmarks, sourced by update_benchmarks.sh and
# bench_real_scans.sh. They expect $bin (the build's bin directory), $rows (a scratch
# directory) and $persistence_runs (runs per measurement).

# The radius at which the complex of the cloud (with the options after the degree)
# has the given average vertex degree (2 edges / points), found by bisection.
radius_for_degree() {
  local input=$1 degree=$2
  shift 2
  "$bin/pcl_tda_bench_persistence" "$input" -find-radius "$degree" "$@" |
    tail -1 | sed 's/.*"radius": \([^,]*\),.*/\1/'
}

# persistence SECTION ARGS...: runs pcl_tda_bench_persistence once with ARGS and
# files the header and the row of each of its tables (end_to_end, h1, incremental)
# under $rows/SECTION, and its JSON line in $rows/SECTION/json. Diagrams that differ (exit status 2) stay in the tables,
# marked DIFFER; any other failure stops the script.
persistence() {
  local section=$1 output status=0
  shift
  mkdir -p "$rows/$section"
  echo "persistence benchmark: $*" >&2
  output=$("$bin/pcl_tda_bench_persistence" "$@" -runs "$persistence_runs") || status=$?
  if [ "$status" -eq 2 ]; then
    echo "persistence benchmark: diagrams differ: pcl_tda_bench_persistence $*" >&2
  elif [ "$status" -ne 0 ]; then
    echo "persistence benchmark: failed: pcl_tda_bench_persistence $*" >&2
    return 1
  fi
  printf '%s\n' "$output" | awk -v dir="$rows/$section" '
    /^### End to end/ { name = "end_to_end"; line = 0; next }
    /^### H1 on the same complex/ { name = "h1"; line = 0; next }
    /^### Incremental/ { name = "incremental"; line = 0; next }
    /^###/ { name = ""; next }
    name != "" && /^\|/ {
      ++line
      if (line <= 2) print > (dir "/" name ".header")
      if (line == 3) print >> (dir "/" name ".rows")
    }'
  printf '%s\n' "$output" | tail -1 >> "$rows/$section/json"
}

# rows_of SECTION TABLE: one header and the rows of that table.
rows_of() {
  cat "$rows/$1/$2.header" "$rows/$1/$2.rows"
}
