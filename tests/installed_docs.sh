#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The installed documentation stands on its own (ctest runs it):
#   1. install fgr into a temporary prefix,
#   2. every relative link of every installed markdown file (the SDK guide's pages in
#      share/fgr/docs/sdk, the pointer to them in share/fgr/sdk, ABI.md, the template's README)
#      resolves to a file or folder inside the prefix,
#   3. the install leaves no empty folder under share/fgr.
#
#   tests/installed_docs.sh BUILD_DIR
set -euo pipefail
build_dir=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
failures=0
fail() { echo "installed_docs: $*" >&2; failures=$((failures + 1)); }

cmake --install "$build_dir" --prefix "$prefix" > "$work/install.log"
for guide in "$prefix/share/fgr/sdk/README.md" "$prefix/share/fgr/docs/sdk/index.md"; do
    [[ -f $guide ]] || { echo "installed_docs: FAILED: no $guide" >&2; exit 1; }
done

# Markdown links [text](target) and images ![alt](target); the target ends at a blank or ')'.
links_in() { grep -o '\]([^) ]*' "$1" | sed 's/^](//' || true; }

checked=0
while IFS= read -r -d '' file; do
    while IFS= read -r target; do
        case $target in
            http://* | https://* | mailto:* | '#'* | '') continue ;;
        esac
        path=${target%%#*}
        resolved=$(realpath -m "$(dirname "$file")/$path")
        checked=$((checked + 1))
        if [[ $resolved != "$prefix"/* ]]; then
            fail "${file#"$prefix"/} links to $target, outside the install prefix"
        elif [[ ! -e $resolved ]]; then
            fail "${file#"$prefix"/} links to $target, which is not installed"
        fi
    done < <(links_in "$file")
done < <(find "$prefix" -name '*.md' -print0)
(( checked > 0 )) || fail "no links found at all: the link pattern is broken"

while IFS= read -r -d '' empty; do
    fail "the install leaves an empty folder ${empty#"$prefix"/}"
done < <(find "$prefix/share/fgr" -type d -empty -print0)

(( failures == 0 )) || { echo "installed_docs: FAILED ($failures problems)" >&2; exit 1; }
echo "installed_docs: $checked relative links resolve inside the prefix, no empty folders"
