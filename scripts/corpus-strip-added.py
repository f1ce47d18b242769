#!/usr/bin/env python3
"""Checks that two report corpora (scripts/report-corpus.sh) differ only by the fields and lines that issue 11
added: in compare JSON (and each batch JSON line's "result") the keys surface_distance.{chamfer, fscore,
fscore_samples, psnr, summary_unavailable}, surface_distance.{forward,backward}.{area_weighted, histogram},
same_connectivity, same_connectivity_unavailable; in compare text the "Summary metrics" block, the
"Same connectivity" block and their blank line. Everything else must be equal (JSON numbers compared exactly,
after parsing; text byte for byte after removing the added lines and normalising the version).

  corpus-strip-added.py OLD_DIR NEW_DIR
"""
import json
import os
import re
import sys

ADDED_SD = ("chamfer", "fscore", "fscore_samples", "psnr", "summary_unavailable")
ADDED_DIR = ("area_weighted", "histogram")
ADDED_TOP = ("same_connectivity", "same_connectivity_unavailable")


def strip_compare(j, stripped):
    if not isinstance(j, dict):
        return j
    if str(j.get("schema", "")).startswith("meshdiff.compare/"):
        for k in ADDED_TOP:
            if k in j:
                stripped.add(k)
                del j[k]
        sd = j.get("surface_distance")
        if isinstance(sd, dict):
            for k in ADDED_SD:
                if k in sd:
                    stripped.add("surface_distance." + k)
                    del sd[k]
            for side in ("forward", "backward"):
                for k in ADDED_DIR:
                    if k in sd.get(side, {}):
                        stripped.add(f"surface_distance.{side}.{k}")
                        del sd[side][k]
    if "result" in j:
        strip_compare(j["result"], stripped)
    return j


def norm_version(text):
    text = re.sub(r"meshdiff [0-9]+\.[0-9]+\.[0-9]+", "meshdiff VERSION", text)
    return re.sub(r'"meshdiff_version": ?"[^"]*"', '"meshdiff_version":"VERSION"', text)


def strip_text(text, stripped):
    out, skip = [], False
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line.startswith("Summary metrics") or line.startswith("Same connectivity"):
            stripped.add("text: " + line.split("(")[0].split(":")[0].strip())
            skip = True
            if line.startswith("Same connectivity") and out and out[-1] == "":
                out.pop()  # its blank line
            if line.startswith("Same connectivity: no") or line.startswith("Summary metrics unavailable"):
                skip = False  # a single line
            continue
        if skip and line.startswith("  "):
            continue
        skip = False
        out.append(line)
    return "\n".join(out)


def parse_json_or_lines(text):
    try:
        return [json.loads(text)]
    except ValueError:
        return [json.loads(line) for line in text.splitlines() if line.strip()]


def main(old_dir, new_dir):
    bad, same, differ_only_added = 0, 0, 0
    stripped = set()
    for root, _, files in os.walk(old_dir):
        for name in sorted(files):
            rel = os.path.relpath(os.path.join(root, name), old_dir)
            a = open(os.path.join(old_dir, rel), "rb").read()
            try:
                b = open(os.path.join(new_dir, rel), "rb").read()
            except FileNotFoundError:
                print("missing:", rel)
                bad += 1
                continue
            if norm_version(a.decode("latin-1")) == norm_version(b.decode("latin-1")):
                same += 1
                continue
            ta, tb = a.decode("latin-1"), b.decode("latin-1")
            ok = False
            if name.endswith((".json", ".jsonl")) or (ta.lstrip().startswith("{") and tb.lstrip().startswith("{")):
                try:
                    ja = [strip_compare(x, set()) for x in parse_json_or_lines(ta)]
                    jb = [strip_compare(x, stripped) for x in parse_json_or_lines(tb)]
                    ok = json.loads(norm_version(json.dumps(ja))) == json.loads(norm_version(json.dumps(jb)))
                except ValueError:
                    ok = False
            else:
                ok = norm_version(strip_text(ta, set())) == norm_version(strip_text(tb, stripped))
            if ok:
                differ_only_added += 1
                print("added fields/lines only:", rel)
            else:
                bad += 1
                print("DIFFERS beyond the added fields:", rel)
    print(f"{same} files identical, {differ_only_added} differ only by the added fields/lines, {bad} differ otherwise")
    print("stripped:", ", ".join(sorted(stripped)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
