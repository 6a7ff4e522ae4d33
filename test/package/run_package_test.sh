#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then configures, builds and runs two
# outside projects that use find_package(PCL_TDA ...): one with the search component
# and the gpu component (and the common one they bring), one with the common component
# alone.
set -euo pipefail
build_dir=$1
source_dir=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > /dev/null
for project in full common_only; do
  cmake -S "$source_dir/$project" -B "$scratch/$project" \
    -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$scratch/$project" > /dev/null
done
"$scratch/full/package_user"
"$scratch/common_only/common_user"
