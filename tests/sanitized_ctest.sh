#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the sanitized tests once, then reruns only those that failed with LeakSanitizer's own
# tracer crash: it now and then crashes while it stops a process's threads at exit (PoCL keeps a
# pool of them), printing "LeakSanitizer has encountered a fatal error" and no report. Any other
# failure (a failed case, a sanitizer's report, a timeout) fails the job without a rerun, so a
# flaky test cannot pass by retrying; every test that was rerun is listed.
# Usage: tests/sanitized_ctest.sh BUILD_DIR JOBS
set -euo pipefail

build_dir=$(cd "$1" && pwd)
jobs=$2
report=$build_dir/Testing/sanitized-first-run.xml
tracer_crash='LeakSanitizer has encountered a fatal error'

if ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" --output-junit "$report" \
    --test-output-size-failed 10000000; then
    exit 0
fi

# The failed tests of the first run, each marked by whether its output shows the tracer crash.
mapfile -t failed < <(python3 - "$report" "$tracer_crash" <<'PY'
import sys
import xml.etree.ElementTree as ElementTree

report, crash = sys.argv[1], sys.argv[2]
# A test that also failed on its own, or that a sanitizer reported, is not the tracer's doing.
other_failures = ("[  FAILED  ]", "ERROR: AddressSanitizer", "ERROR: LeakSanitizer: detected",
                  "runtime error:")
for case in ElementTree.parse(report).getroot().iter("testcase"):
    if case.get("status") != "fail":
        continue
    output = "".join(node.text or "" for node in case.iter("system-out"))
    tracer = crash in output and not any(failure in output for failure in other_failures)
    print(("tracer " if tracer else "other ") + case.get("name"))
PY
)
rerun=()
other=()
for line in "${failed[@]}"; do
    if [[ $line == tracer\ * ]]; then rerun+=("${line#tracer }"); else other+=("${line#other }"); fi
done
if ((${#other[@]} > 0)); then
    echo "sanitized_ctest.sh: failed for a reason other than LeakSanitizer's tracer crash" \
        "(not rerun): ${other[*]}" >&2
    exit 1
fi
if ((${#rerun[@]} == 0)); then
    echo "sanitized_ctest.sh: ctest failed but named no failed test ($report)" >&2
    exit 1
fi
echo "sanitized_ctest.sh: rerunning after LeakSanitizer's tracer crash: ${rerun[*]}" >&2
pattern=$(printf '%s\n' "${rerun[@]}" | sed 's/[][\.*^$+?(){}|]/\\&/g' | paste -sd '|')
ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" -R "^(${pattern})\$"
echo "sanitized_ctest.sh: passed on their rerun: ${rerun[*]}" >&2
