#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the test suite of ./build-asan (packaging/build-sanitize.sh) under AddressSanitizer,
# LeakSanitizer and UndefinedBehaviorSanitizer: any report fails its test. Leaves out three tests
# that take minutes at this speed and check nothing the sanitizers add to (the 2-million-triangle
# mesh, the end-to-end detection run, the repeated kill of training); the Release suite runs them.
# Of the public API's tests, which each train the sample part again, it keeps those that reach
# code the others do not (threads, bad captures, NaN depth, JSON, training, damaged archives).
# The Python module is not built here (build-sanitize.sh), so its tests do not run.
set -euo pipefail
cd "$(dirname "$0")/.."
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
ctest --test-dir build-asan --output-on-failure -j2 \
  -E 'HugeMeshTest\.TwoMillion|CanDetectionTest|CliKillTest\.TargetHolds|ApiArchiveTest\.(LoadGives|SaveThenLoad|CopiesShare)|ApiVersionTest\.|ApiDetectorTest\.(FindsThePart|SixteenBit|OptionsUse)' "$@"
