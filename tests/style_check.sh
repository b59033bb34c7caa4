#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# style_check.sh REPO: the style the tree keeps (.clang-format, ../shared/STYLE.md), checked so a
# change that breaks it fails. Prints every offence and exits 1, or exits 0 when there is none:
#   - C, C++ and OpenCL C sources are as clang-format writes them (includes sorted, 100 columns);
#   - no C, C++ or OpenCL C line is over 100 columns;
#   - comments and user docs say why, not when: no "issue N" (git log keeps the history);
#   - every source file carries its SPDX licence line;
#   - OpenCL C stays 1.2, which every driver takes: no variadic macro (NVIDIA's compiler refuses
#     them, where PoCL's newer Clang lets them pass).
# Frozen copies of old ABI headers and kernel libraries are left as they were frozen, and the
# `fgr new-scene` template, which is C only once its @PLACEHOLDERS@ are filled in.
set -euo pipefail
cd "$1"
frozen='^(tests/(abi_v1[^/]*|fixtures/frozen_v1[^/]*|fixtures/kernel_api_v1)/|sdk/template/)'
failures=0

report=$(mktemp)
trap 'rm -f "$report"' EXIT
mapfile -t sources < <(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' '*.cl' | grep -Ev "$frozen")
if ! clang-format --dry-run --Werror "${sources[@]}" 2>"$report"; then
    grep -E '^[^ ].*(warning|error):' "$report" | head -n 40 || true
    echo "clang-format would change $(grep -c 'error:' "$report") places: run"
    echo "  clang-format -i \$(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' '*.cl' | grep -Ev '$frozen')"
    failures=$((failures + 1))
fi

# clang-format leaves alone what it cannot break (a long word, a raw string): lines are counted
# in characters, so a comment's θ or ² is one column.
mapfile -t all_sources < <(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' '*.cl' | grep -Ev "$frozen")
if long=$(LC_ALL=C.UTF-8 grep -nE '^.{101,}' "${all_sources[@]}") && [[ -n $long ]]; then
    echo "$long" | cut -c1-160
    echo "lines over 100 columns"
    failures=$((failures + 1))
fi

if history=$(git grep -nE '\b[Ii]ssue [0-9]+' -- host kernels plugin_api plugins sdk tests docs \
    README.md CMakeLists.txt cmake build.sh bench ':!tests/style_check.sh') && [[ -n $history ]]; then
    echo "$history"
    echo "say why, not which issue: the history is in git log"
    failures=$((failures + 1))
fi

# Every source file names its licence (SPDX), so a file copied out of the tree keeps it. The
# frozen copies stay as they were frozen; the scene template becomes the author's own file.
mapfile -t licensed < <(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' '*.cl' '*.cmake' '*.sh' '*.py' \
    '*.gp' '*.in' '*.supp' '*CMakeLists.txt' .ci/run | grep -Ev "$frozen")
if unlicensed=$(grep -L 'SPDX-License-Identifier: Apache-2.0' "${licensed[@]}") &&
    [[ -n $unlicensed ]]; then
    echo "$unlicensed"
    echo "no SPDX-License-Identifier line: add '// SPDX-License-Identifier: Apache-2.0' (or '#')"
    failures=$((failures + 1))
fi

mapfile -t kernel_sources < <(git ls-files '*.cl' | grep -Ev "$frozen")
if variadic=$(grep -nE '^[[:space:]]*#[[:space:]]*define[[:space:]]+[A-Za-z_0-9]+\([^)]*\.\.\.' \
    "${kernel_sources[@]}") && [[ -n $variadic ]]; then
    echo "$variadic"
    echo "variadic macros are not OpenCL C 1.2: give the macro named parameters"
    failures=$((failures + 1))
fi

((failures == 0)) || exit 1
echo "style: clang-format clean, no line over 100 columns, no issue numbers, every source licensed,"
echo "  no variadic macros"
