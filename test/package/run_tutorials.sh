#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then configures, builds and runs every
# tutorial project of doc/tutorials/ as an outside project that uses
# find_package(PCL_TDA ...). Each program is run with the command line its page
# gives (the line "$ ./<name> ..."), from a scratch folder, with ../shared/data/ read
# as the data folder beside the repository; a run whose data file is absent is
# skipped with a message.
set -euo pipefail
shopt -s nullglob
build_dir=$(cd "$1" && pwd)
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
tutorials=$source_dir/doc/tutorials
data_dir=$source_dir/../shared/data
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > /dev/null
found=0
# Prints the first fenced block of language $2 of the page $1.
page_block() {
  awk -v fence="\`\`\`$2" '$0 == fence { inside = 1; next } inside && $0 == "```" { exit } inside' "$1"
}
for project in "$tutorials"/*/; do
  project=${project%/}
  name=$(basename "$project")
  found=$((found + 1))
  # The page shows the program and its CMakeLists.txt as they are.
  if ! diff -u "$project/$name.cpp" <(page_block "$tutorials/$name.md" cpp) ||
     ! diff -u "$project/CMakeLists.txt" <(page_block "$tutorials/$name.md" cmake); then
    echo "$name: $name.md does not show $name/$name.cpp and $name/CMakeLists.txt" \
         "as they are (see the differences above)" >&2
    exit 1
  fi
  # PCL's package prints warnings of its own: show the log only when a step fails.
  if ! cmake -S "$project" -B "$scratch/build/$name" -DCMAKE_PREFIX_PATH="$scratch/prefix" \
         -DCMAKE_BUILD_TYPE=Release > "$scratch/$name.log" 2>&1 ||
     ! cmake --build "$scratch/build/$name" >> "$scratch/$name.log" 2>&1; then
    cat "$scratch/$name.log" >&2
    echo "$name: configuring or building failed" >&2
    exit 1
  fi
  if ! grep -q "^ *\\\$ \\./$name\\( \\|\$\\)" "$tutorials/$name.md"; then
    echo "$name: its page $name.md has no line '\$ ./$name ...' to run" >&2
    exit 1
  fi
  command_line=$(sed -n "s|^ *\\\$ \\./$name\\( \\(.*\\)\\)\\?\$|\\2|p" \
                   "$tutorials/$name.md" | head -n 1)
  args=()
  missing=""
  for arg in $command_line; do
    case $arg in
      ../shared/data/*)
        [[ -f $data_dir/${arg#../shared/data/} ]] || missing=$arg
        arg=$data_dir/${arg#../shared/data/}
        ;;
    esac
    args+=("$arg")
  done
  if [[ -n $missing ]]; then
    echo "$name: built; run skipped: the data file $missing is absent (folder $data_dir)"
    continue
  fi
  mkdir -p "$scratch/run/$name"
  echo "$name: running ./$name $command_line"
  (cd "$scratch/run/$name" && "$scratch/build/$name/$name" "${args[@]}")
done
if [[ $found -eq 0 ]]; then
  echo "no tutorial project in $tutorials" >&2
  exit 1
fi
