#!/usr/bin/env python3
"""The batch summary page (meshdiff batch-summary --html) in a real browser:
headless Debian chromium driven by selenium opens a summary of a small batch
(two pairs with their --html-dir pages, one failed pair, one missing pair)
through file:// with the network off, and checks that
  - the page logs no console error and asks for no resource (all inlined);
  - the embedded records are the batch's, one table row per record;
  - every cell of the table equals the embedded JSON's value at its path;
  - clicking a header sorts the rows numerically (again: the other way),
    empty cells last;
  - each measure is plotted, and the per-pair links point to existing files.
Usage: html_summary_browser_test.py MESHDIFF DATA_DIR WORK_DIR
Exit 77 (a skip for ctest) only when chromium, chromedriver or selenium is
missing, and then 1 with MESHDIFF_REQUIRE_BROWSER=1 (scripts/test.sh)."""
import json
import os
import shutil
import subprocess
import sys
import urllib.parse

SKIP = 1 if os.environ.get("MESHDIFF_REQUIRE_BROWSER") == "1" else 77
CHROMIUM = shutil.which("chromium")
DRIVER = "/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else shutil.which("chromedriver")
try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError as e:
    print(f"SKIP: {e} (scripts/install-deps.sh installs python3-selenium)")
    sys.exit(SKIP)
if not CHROMIUM or not DRIVER:
    print("SKIP: chromium or chromedriver not installed (scripts/install-deps.sh installs them)")
    sys.exit(SKIP)

cli, data, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, "summary"))
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(*args, codes=(0,)):
    r = subprocess.run([cli, *args], capture_output=True, text=True, cwd=work)
    if r.returncode not in codes:
        sys.exit(f"meshdiff {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return r


A, B, H = (os.path.join(data, f) for f in ("bunny_res3.ply", "bunny_res4_ascii.ply", "hemisphere.ply"))
with open(os.path.join(work, "pairs.csv"), "w") as f:
    f.write(f"{A},{B},bunny pair\n{B},{A},reversed\n{A},{os.path.join(data, 'missing.ply')},bad\n{A},{H},later\n")
with open(os.path.join(work, "pairs3.csv"), "w") as f:  # the batch runs the first three; "later" stays missing
    f.write("".join(open(os.path.join(work, "pairs.csv")).readlines()[:3]))
run("batch", "pairs3.csv", "--out", "r.jsonl", "--html-dir", "pages", "--levels", "1,2,5", "-q", codes=(6,))
run("batch-summary", "r.jsonl", "--pairs", "pairs.csv", "--html", "summary/s.html", "-q", codes=(6,))
page = os.path.join(work, "summary", "s.html")
lines = {r["id"]: r for r in map(json.loads, open(os.path.join(work, "r.jsonl")))}
expected = [lines.get(i, {"id": i, "status": "missing"}) for i in ("bunny pair", "reversed", "bad", "later")]

options = webdriver.ChromeOptions()
options.binary_location = CHROMIUM
for flag in ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1200,1000"]:
    options.add_argument(flag)
options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
driver = webdriver.Chrome(service=Service(DRIVER), options=options)
try:
    driver.set_page_load_timeout(30)
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions",
                           {"offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
    driver.get("file://" + page)
    check(driver.execute_script("return !!window.meshdiffSummary"), "the page's script ran")
    resources = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
    check(resources == [], f"no resource requested (inlined page): {resources}")

    embedded = driver.execute_script("return JSON.parse(document.getElementById('meshdiff-summary').textContent)")
    check(embedded == expected, "the embedded records are the batch's, in the pair list's order")
    n_rows = driver.execute_script("return document.querySelectorAll('#pairs tbody tr').length")
    check(n_rows == len(embedded), f"one row per record ({n_rows} rows, {len(embedded)} records)")

    cells = driver.execute_script(
        "return [...document.querySelectorAll('#pairs tbody tr')].flatMap(tr => [...tr.cells].map(td => "
        "[Number(tr.dataset.index), td.dataset.key, td.dataset.path || null, td.textContent, "
        "td.dataset.value === undefined ? null : td.dataset.value]))")

    def at(x, path):
        for k in path.split("."):
            x = x[int(k)] if isinstance(x, list) else x[k]
        return x

    bad, numbers = [], 0
    for i, key, path, text, value in cells:
        if path is None:
            continue
        v = at(embedded[i], path)
        if isinstance(v, str):
            ok = text == v and value is None
        else:
            numbers += 1
            ok = float(value) == v and float(text) == float(f"{v:.6g}")
        if not ok:
            bad.append((i, key, path, text, value, v))
    check(numbers >= 2 * 12 and not bad, f"{numbers} numeric cells equal the embedded JSON (mismatches: {bad[:5]})")
    keys = {k for _, k, p, _, _ in cells if p}
    for needed in ["hausdorff", "hausdorff_relative", "forward_mean", "forward_rms", "backward_mean", "backward_rms",
                   "d_L1", "d_L2", "d_L5", "d_global", "local_L1", "local_L5", "local_global", "error"]:
        check(needed in keys, f"the table shows {needed}")
    errors_shown = [t for _, k, _, t, _ in cells if k == "error" and t]
    check(errors_shown == [lines["bad"]["error"]], f"the failed pair's error is listed: {errors_shown}")

    def column(key):
        return driver.execute_script(
            "return [...document.querySelectorAll('#pairs tbody tr')].map(tr => { const td = "
            "tr.querySelector('td[data-key=\"' + arguments[0] + '\"]'); return td.dataset.value === undefined ? "
            "null : Number(td.dataset.value); })", key)

    for key in ("forward_rms", "local_L1"):
        driver.find_element("css selector", f'#pairs th[data-key="{key}"]').click()
        up = column(key)
        driver.find_element("css selector", f'#pairs th[data-key="{key}"]').click()
        down = column(key)
        vals = [x for x in up if x is not None]
        check(vals == sorted(vals) and up[len(vals):] == [None] * (len(up) - len(vals)) and len(vals) == 2,
              f"a click on {key} sorts numerically, empty cells last: {up}")
        dvals = [x for x in down if x is not None]
        check(dvals == sorted(vals, reverse=True) and down[len(dvals):] == [None] * (len(down) - len(dvals)),
              f"a second click sorts the other way: {down}")
    driver.find_element("css selector", '#pairs th[data-key="id"]').click()
    ids = driver.execute_script(
        "return [...document.querySelectorAll('#pairs tbody td[data-key=\"id\"]')].map(td => td.textContent)")
    check(ids == sorted(ids, key=lambda s: s.lower()), f"a click on id sorts by text: {ids}")

    plots = driver.execute_script("return [...document.querySelectorAll('svg.plot')].map(s => s.id)")
    check({"plot-hausdorff", "plot-forward_rms", "plot-d_L1", "plot-local_L1"} <= set(plots), f"plots: {plots}")
    bars = driver.execute_script("return document.querySelectorAll('#plot-hausdorff rect.bar').length")
    check(bars == 2, f"the Hausdorff plot has a bar per pair with a value ({bars})")

    links = driver.execute_script("return [...document.querySelectorAll('#pairs a')].map(a => "
                                  "[a.closest('tr').querySelector('td[data-key=\"id\"]').textContent, "
                                  "a.getAttribute('href'), a.href])")
    check(sorted(i for i, _, _ in links) == ["bunny pair", "reversed"], f"a link per pair with a page: {links}")
    for i, rel, url in links:
        target = urllib.parse.unquote(urllib.parse.urlparse(url).path)
        check(not rel.startswith("/") and not rel.startswith("file:") and os.path.isfile(target) and
              os.path.samefile(target, os.path.join(work, lines[i]["html"])),
              f"{i}: the link {rel} is relative and points to its page")
    check("batch-summary" in driver.find_element("id", "command").text, "the page shows the command line")
    check("meshdiff " in driver.find_element("id", "version").text, "the page shows the version")

    errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
    check(not errors, f"no console error: {errors}")
finally:
    driver.quit()

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
