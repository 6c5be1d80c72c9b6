#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every libFuzzer target of ./build-asan (made by packaging/build-sanitize.sh) for a bounded
# time: bash packaging/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]. The mutation seed is fixed
# (FUZZ_SEED, default 1), so a short CI run retraces the start of a longer local run.
# Each target starts from the project's seed corpus plus the committed regression inputs and
# keeps its grown corpus in build-asan/fuzz/corpus/<target>. A crash, leak, timeout or
# sanitizer report stops with a non-zero exit; the input is kept in build-asan/fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(archive capture bop profile mesh)

work=build-asan/fuzz
seeds="$work/seeds"
mkdir -p "$work"
build-asan/tests/fuzz/layermod_fuzz_seeds "$seeds" ../shared/data > /dev/null

export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
status=0
for target in "${targets[@]}"; do
  corpus="$work/corpus/$target"
  findings="$work/findings/$target"
  mkdir -p "$corpus" "$findings"
  inputs=("$corpus" "$seeds/$target")
  [ -d "tests/fuzz/regressions/$target" ] && inputs+=("tests/fuzz/regressions/$target")
  log="$work/$target.log"
  if build-asan/tests/fuzz/layermod_fuzz_"$target" -seed="${FUZZ_SEED:-1}" \
      -max_total_time="$seconds" -timeout=20 \
      -rss_limit_mb=4096 -max_len=262144 -print_final_stats=1 \
      -artifact_prefix="$findings/" "${inputs[@]}" > "$log" 2>&1; then
    result="ok"
  else
    result="FAILED (see $log and $findings)"
    status=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo "?")
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  echo "fuzz $target: $runs executions in ${seconds}s, $coverage, $result"
done
exit $status
