#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# user_docs_check.sh REPO: the text users read is written for them, not as a record of how it was
# made: no issue numbers, no "the brief", no "lab notebook", no "this session" in the README, the
# changes, the documentation site's pages, the SDK's guide and template, the ABI, the benchmark
# reports and the golden set's guide. Prints every offence and exits 1, or exits 0 when there is
# none. (StyleCheck keeps issue numbers out of the sources' comments too.)
set -euo pipefail
cd "$1"
mapfile -t files < <(git ls-files README.md CHANGES.md SECURITY.md 'docs/*.md' 'sdk/*.md' plugin_api/ABI.md \
    'bench/*.md' tests/golden/README.md)
((${#files[@]} > 5)) || { echo "user_docs_check: only ${#files[@]} files found: is REPO right?"; exit 1; }
if found=$(grep -n -i -E '\bissues? #?[0-9]+|\bthe brief\b|\blab notebook\b|\bthis session\b' \
    "${files[@]}"); then
    echo "$found"
    echo "user_docs_check: write for the reader: say what is, not which issue, brief or session" \
        "it came from (git log keeps the history)"
    exit 1
fi
echo "user_docs_check: ${#files[@]} files read by users, no bookkeeping words"
