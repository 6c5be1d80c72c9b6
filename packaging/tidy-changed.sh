#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs clang-tidy (.clang-tidy, warnings as errors) on the C++ sources changed since BASE
# (default: the commit in .ci/tidy-base) and fails on any warning. Needs ./build configured
# (compile_commands.json). Headers are checked through the sources that include them.
set -euo pipefail
cd "$(dirname "$0")/.."
base="${1:-$(cat .ci/tidy-base)}"
if ! git cat-file -e "${base}^{commit}" 2>/dev/null; then
  if [[ -f .git/shallow ]]; then
    echo "tidy-changed: warning: shallow clone without ${base:0:12}; nothing checked" >&2
    exit 0
  fi
  echo "tidy-changed: '${base}' is not a commit of this repository" >&2
  exit 2
fi
[[ -f build/compile_commands.json ]] || { echo "tidy-changed: run packaging/build.sh first" >&2; exit 2; }
mapfile -t changed < <(git diff --name-only --diff-filter=AMR "${base}" -- \
  'core/*.cpp' 'app/*.cpp' 'ui/*.cpp' 'python/*.cpp')
# Only sources the build compiles (compile_commands.json knows them).
files=()
for file in "${changed[@]}"; do
  grep -q "\"file\": \"$(pwd)/${file}\"" build/compile_commands.json && files+=("${file}")
done
echo "tidy-changed: ${#files[@]} changed source(s) since ${base:0:12}"
[[ ${#files[@]} -eq 0 ]] && exit 0
# pybind11 builds the module with -fno-fat-lto-objects, which clang does not know: not an
# error of the code.
printf '%s\0' "${files[@]}" | xargs -0 -n 4 -P "$(nproc)" clang-tidy -p build --quiet \
  --extra-arg=-Wno-ignored-optimization-argument
echo "tidy-changed: no warnings"
