#!/usr/bin/env bash
# Checks that every code block marked in a Markdown file as
#   <!-- example: PATH -->
#   ```cpp
#   ...
#   ```
#   <!-- end example -->
# is byte-identical to PATH (relative to the repository root), so that the
# documented example is the one that is compiled.
# Usage: tests/doc_example_test.sh FILE.md...
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
status=0
checked=0
for md in "$@"; do
    while IFS= read -r path; do
        block=$(mktemp)
        # The lines strictly between the fence after the marker and the fence
        # before the end marker; fails without the end marker.
        if ! awk -v want="<!-- example: $path -->" '
            $0 == want { state = 1; next }
            state == 1 && /^```/ { state = 2; next }
            state == 2 && /^```$/ { state = 3; next }
            state == 2 { print; next }
            state == 3 && $0 == "<!-- end example -->" { state = 4; exit }
            END { if (state != 4) exit 1 }
        ' "$md" >"$block"; then
            echo "FAIL: $md: no closed block for $path (fence, then <!-- end example -->)" >&2
            status=1
        elif cmp -s "$block" "$root/$path"; then
            echo "ok: $md shows $path"
        else
            echo "FAIL: the example in $md differs from $path:" >&2
            diff -u "$root/$path" "$block" >&2 || true
            status=1
        fi
        rm -f "$block"
        checked=$((checked + 1))
    done < <(sed -n 's/^<!-- example: \(.*\) -->$/\1/p' "$md")
done
if ((checked == 0)); then
    echo "FAIL: no <!-- example: PATH --> marker in $*" >&2
    exit 1
fi
exit "$status"
