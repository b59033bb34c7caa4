#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# architecture_check.sh CONCEPTS HOST_DIR: the host's folders use only what their targets link.
#
# CONCEPTS (host_concepts.txt, written by host/CMakeLists.txt) has one line per host folder:
# "folder: linked-folder...". A folder may include "<other>/..." headers only for the folders its
# target reaches through its links, directly or not, and the links may not form a cycle. Prints
# each offending include or cycle and exits 1; exits 0 when there is none.
set -euo pipefail
concepts_file=$1
host_dir=$2

declare -A links
folders=()
while IFS=: read -r folder used; do
    [[ -z $folder ]] && continue
    folders+=("$folder")
    links[$folder]=$used
done <"$concepts_file"

declare -A state reach cycle_reported
failures=0

# visit FOLDER: fills reach[FOLDER] with every folder it reaches; reports a cycle through it.
visit() {
    local folder=$1
    [[ ${state[$folder]:-} == done ]] && return 0
    if [[ ${state[$folder]:-} == open ]]; then
        [[ -n ${cycle_reported[$folder]:-} ]] && return 0
        echo "cycle: the links of $folder lead back to it"
        cycle_reported[$folder]=1
        failures=$((failures + 1))
        return 0
    fi
    state[$folder]=open
    local all=" " next
    for next in ${links[$folder]:-}; do
        visit "$next"
        all+="$next ${reach[$next]:-} "
    done
    reach[$folder]=$all
    state[$folder]=done
}

pattern=$(IFS='|'; echo "${folders[*]}")
for folder in "${folders[@]}"; do
    visit "$folder"
    [[ -d $host_dir/$folder ]] || continue
    while IFS= read -r hit; do
        file=${hit%%:*}
        rest=${hit#*:}
        line=${rest%%:*}
        used=$(sed -E "s/.*#include \"($pattern)\/.*/\1/" <<<"$rest")
        [[ $used == "$folder" || ${reach[$folder]} == *" $used "* ]] && continue
        echo "${file#"$host_dir"/}:$line includes $used/, which $folder does not link"
        failures=$((failures + 1))
    done < <(grep -rnE "#include \"($pattern)/" "$host_dir/$folder" || true)
done
if ((failures > 0)); then
    echo "$failures problem(s) with who may use whom (the links are in host/*/CMakeLists.txt)"
    exit 1
fi
echo "${#folders[@]} host folders: every include follows the links, and the links have no cycle"
