#!/usr/bin/env bash
# Replays every hostile input that ever failed (tests/fuzz/regressions/<format>/,
# found by scripts/fuzz.sh, and the hand-made tests/data/hostile/) through
# `meshdiff profile` and `meshdiff A A`: each must end within 10 s with exit 0,
# 3 or 4 and a one-line message, never a signal, exit 70 or a NaN in a report.
# Usage: replay_hostile.sh MESHDIFF_BINARY TESTS_DIR
bin="$1"
dir=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$dir/cli_lib.sh"

n=0
while IFS= read -r -d '' f; do
    case "$f" in */README.md | */PROVENANCE.md) continue ;; esac
    # The format follows the folder (regressions/<format>/) or the file's own extension.
    ext="${f##*.}"
    parent=$(basename "$(dirname "$f")")
    case "$parent" in ply | obj | off | stl) ext="$parent" ;; esac
    cp "$f" "$tmp/input.$ext"
    for cmd in profile compare; do
        if [ "$cmd" = profile ]; then
            args=(profile "$tmp/input.$ext" --levels 1,2 --json "$tmp/out.json")
        else
            args=("$tmp/input.$ext" "$tmp/input.$ext" --levels 1 -n 2000 --json "$tmp/out.json")
        fi
        rm -f "$tmp/out.json"
        timeout 10 "$bin" "${args[@]}" > "$tmp/stdout" 2> "$tmp/stderr"
        code=$?
        n=$((n + 1))
        case "$code" in
            0)
                if grep -qi "nan" "$tmp/stdout" || { [ -f "$tmp/out.json" ] && grep -q "null" "$tmp/out.json" &&
                    python3 -c "import json,sys,math
j=json.load(open(sys.argv[1]))
def bad(x):
    if isinstance(x, dict): return any(bad(v) for v in x.values())
    if isinstance(x, list): return any(bad(v) for v in x)
    return isinstance(x, float) and not math.isfinite(x)
sys.exit(0 if bad(j) else 1)" "$tmp/out.json"; }; then
                    fail "$f ($cmd): a NaN in the report"
                else
                    pass
                fi
                ;;
            3 | 4)
                [ "$(wc -l < "$tmp/stderr")" -eq 1 ] && pass || fail "$f ($cmd): exit $code with $(wc -l < "$tmp/stderr") lines on stderr"
                ;;
            124) fail "$f ($cmd): no end within 10 s" ;;
            *) fail "$f ($cmd): exit $code: $(head -c 300 "$tmp/stderr")" ;;
        esac
    done
done < <(find "$dir/fuzz/regressions" "$dir/data/hostile" -type f -print0 2> /dev/null | sort -z)
echo "replayed $n runs"
finish
