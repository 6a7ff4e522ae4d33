#!/usr/bin/env bash
# Fails, listing the files, when a tracked C++ file is not formatted by the project's
# .clang-format (PCL's). Fix with: clang-format -i FILE...
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.h' '*.hpp' '*.cpp')
unformatted=()
for file in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$file" > /dev/null 2>&1; then
    unformatted+=("$file")
  fi
done
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "check_format: ${#unformatted[@]} of ${#files[@]} files need clang-format -i:"
  printf '  %s\n' "${unformatted[@]}"
  exit 1
fi
echo "check_format: all ${#files[@]} C++ files are formatted"
