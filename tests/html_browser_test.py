#!/usr/bin/env python3
"""The HTML report in a real browser: headless Debian chromium driven by
selenium opens a report made from the bundled bunnies through file:// with
the network off, and checks that
  - the page logs no console error and asks for no resource (all inlined);
  - the WebGL canvas draws the meshes in the colour map's colours (a
    screenshot's pixels lie on the PLY maps' ramp), and the vertex colours of
    the page are those of the PLY distance map for the same range;
  - switching to a roughness level changes the picture (to the D_L ramp);
  - every number of the page's tables equals the embedded JSON's, which is
    the CLI's --json report;
  - the certified Hausdorff marker sits at the reported point (in the page's
    data and on screen).
Usage: html_browser_test.py MESHDIFF DATA_DIR WORK_DIR
Exit 77 (a skip for ctest) only when chromium, chromedriver or selenium is
missing, and then 1 with MESHDIFF_REQUIRE_BROWSER=1 (scripts/test.sh, after
scripts/install-deps.sh installed them). With
MESHDIFF_UPDATE_SCREENSHOT=1 the screenshot is also copied to
docs/html-report.png (shown in README.md)."""
import io
import json
import math
import os
import shutil
import subprocess
import sys
import time

# scripts/test.sh sets MESHDIFF_REQUIRE_BROWSER=1: there, where install-deps.sh installed them, a missing
# browser is a failure, not a skip.
SKIP = 1 if os.environ.get("MESHDIFF_REQUIRE_BROWSER") == "1" else 77
CHROMIUM = shutil.which("chromium")
DRIVER = "/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else shutil.which("chromedriver")
try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from PIL import Image
except ImportError as e:
    print(f"SKIP: {e} (scripts/install-deps.sh installs python3-selenium and python3-pil)")
    sys.exit(SKIP)
if not CHROMIUM or not DRIVER:
    print("SKIP: chromium or chromedriver not installed (scripts/install-deps.sh installs them)")
    sys.exit(SKIP)

cli, data, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
A, B = os.path.join(data, "bunny_res3.ply"), os.path.join(data, "bunny_res4_ascii.ply")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(*args):
    r = subprocess.run([cli, *args], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"meshdiff {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return r


def read_ply_colors(path):
    """The red, green, blue of every vertex of a PLY written by meshdiff (ASCII or binary little endian)."""
    import numpy as np
    raw = open(path, "rb").read()
    end = raw.index(b"end_header\n") + len(b"end_header\n")
    header = raw[:end].decode().splitlines()
    fmt, props, n = header[1].split()[1], [], 0
    sizes = {"float": "<f4", "double": "<f8", "uchar": "u1", "int": "<i4", "uint": "<u4", "float32": "<f4",
             "float64": "<f8", "uint8": "u1"}
    element = None
    for line in header:
        w = line.split()
        if w[0] == "element":
            element = w[1]
            if element == "vertex":
                n = int(w[2])
        elif w[0] == "property" and element == "vertex":
            props.append((w[2], sizes[w[1]]))
    if fmt == "ascii":
        rows = raw[end:].decode().splitlines()[:n]
        names = [p[0] for p in props]
        return [tuple(int(float(r.split()[names.index(c)])) for c in ("red", "green", "blue")) for r in rows]
    v = np.frombuffer(raw, dtype=np.dtype(props), count=n, offset=end)
    return list(zip(v["red"].tolist(), v["green"].tolist(), v["blue"].tolist()))


# The report, with the JSON of the same run and both PLY maps on the same explicit colour range.
html, js = os.path.join(work, "report.html"), os.path.join(work, "report.json")
run(A, B, "--html", html, "--json", js)
ranged, maps = os.path.join(work, "ranged.html"), os.path.join(work, "maps")
run(A, B, "--html", ranged, "--distance-maps", maps, "--color-range", "0", "0.004")
cli_json = json.load(open(js))
print(f"report: {os.path.getsize(html):,} bytes")

options = webdriver.ChromeOptions()
options.binary_location = CHROMIUM
for flag in ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1200,1400",
             "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--force-device-scale-factor=1",
             "--allow-file-access-from-files"]:
    options.add_argument(flag)
options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
driver = webdriver.Chrome(service=Service(DRIVER), options=options)
try:
    driver.set_page_load_timeout(60)
    # Network off: any request to the network fails (and would show as a console error).
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions",
                           {"offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})

    def open_page(path):
        t0 = time.time()
        driver.get("file://" + os.path.abspath(path))
        for _ in range(600):
            if driver.execute_script("return !!(window.meshdiffReport && window.meshdiffReport.state.frames > 0)"):
                break
            time.sleep(0.05)
        return time.time() - t0

    def frame():
        """The canvas as an RGB image, after the next frame is drawn."""
        n = driver.execute_script("return window.meshdiffReport.state.frames")
        for _ in range(200):
            if driver.execute_script("return window.meshdiffReport.state.frames") > n:
                break
            time.sleep(0.02)
        view = driver.find_element("id", "view")
        driver.execute_script("arguments[0].scrollIntoView()", view)  # a screenshot keeps only what is in view
        png = view.screenshot_as_png
        return Image.open(io.BytesIO(png)).convert("RGB")

    load = open_page(html)
    print(f"loaded and drawn in {load:.2f} s")
    check(driver.execute_script("return window.meshdiffReport.state.error") is None, "WebGL context created")
    resources = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
    check(resources == [], f"no resource requested (inlined page): {resources}")

    # Numbers: the embedded JSON is the CLI's; every table cell is the JSON's value at its key.
    embedded = driver.execute_script("return JSON.parse(document.getElementById('meshdiff-report').textContent)")
    check(embedded == cli_json, "the embedded JSON equals the CLI's --json report")
    cells = driver.execute_script(
        "return [...document.querySelectorAll('td[data-key]')].map(td => [td.dataset.key, td.textContent, "
        "td.dataset.value === undefined ? null : td.dataset.value])")

    def at(path):
        x = cli_json
        for k in path.split("."):
            x = x[int(k)] if isinstance(x, list) else x[k]
        return x

    bad = []
    for key, text, value in cells:
        v = at(key)
        if isinstance(v, bool) or v is None or isinstance(v, str):
            continue
        if float(value) != v or (not isinstance(v, int) and float(text) != float(f"{v:.6g}")) or (
                isinstance(v, int) and int(text) != v):
            bad.append((key, text, value, v))
    keys = {k for k, _, _ in cells}
    check(not bad, f"{len(cells)} table cells equal the JSON (mismatches: {bad[:5]})")
    for needed in ["surface_distance.hausdorff.lower", "surface_distance.hausdorff.upper",
                   "surface_distance.hausdorff.relative.upper", "surface_distance.forward.mean",
                   "surface_distance.backward.rms", "surface_distance.forward.p99", "original.mesh.vertices",
                   "processed.mesh.faces", "original.mesh.components", "roughness_distance.distance.0",
                   "roughness_distance.global.distance", "original.sigma.19", "processed.sigma_global",
                   "roughness_distance.local.rms.0", "roughness_distance.local.rms.19",
                   "roughness_distance.local.global"]:
        check(needed in keys, f"the table shows {needed}")
    check(driver.find_element("id", "local-definition").text.startswith("local RMS: rms_L = "),
          "the local RMS column is defined under the table")
    check("--html" in driver.find_element("id", "command").text, "the page shows the command line")
    check(len(driver.find_elements("css selector", "svg.plot")) >= 4, "sigma, d_L and both histograms plotted")

    # The Hausdorff marker: at the reported point, on the mesh whose samples reach it, and drawn there.
    h = cli_json["surface_distance"]["hausdorff"]
    loc = cli_json["surface_distance"][h["attained"]]["hausdorff"]["location"]
    on = 0 if h["attained"] == "forward" else 1
    markers = driver.execute_script("return window.meshdiffReport.markerPositions()")
    check(all(abs(a - b) <= 1e-12 * max(1, abs(b)) for a, b in zip(markers[on][0], loc["point"])),
          f"marker at the reported point {loc['point']} (page: {markers[on][0]})")
    check(all(abs(a - b) <= 1e-12 * max(1, abs(b)) for a, b in zip(markers[1 - on][0], loc["closest_point"])),
          "its closest point marked on the other mesh")

    # The picture: flat colours (no shading) are the ramp's own colours.
    driver.execute_script("window.meshdiffReport.setShading(false); window.meshdiffReport.setField('distance')")
    img = frame()
    px = list(img.getdata())

    def on_sequential(c, tol=6):
        r, g, b = c
        return ((r <= tol and b >= 255 - tol) or (r <= tol and g >= 255 - tol) or (b <= tol and g >= 255 - tol)
                or (b <= tol and r >= 255 - tol))

    surface = [c for c in px if c != (255, 255, 255) and not (c[0] > 200 and c[1] < 60 and c[2] > 200)]
    ramp = [c for c in surface if on_sequential(c)]
    check(len(surface) > 0.05 * len(px), f"the meshes cover {len(surface) / len(px):.0%} of the canvas")
    # Colours interpolate across a triangle (between ramp segments they leave the ramp) and edges are smoothed:
    # most pixels, not all, lie on it; the vertex colours themselves are checked exactly below.
    check(len(ramp) > 0.5 * len(surface), f"{len(ramp) / max(1, len(surface)):.0%} of surface pixels on the ramp")
    hues = {("blue" if c[2] > 200 and c[1] < 128 else "cyan" if c[2] > 128 else "green" if c[0] < 128 else
             "yellow" if c[1] > 128 else "red") for c in ramp}
    check(len(hues) >= 3, f"the ramp's colours appear: {sorted(hues)}")
    p = driver.execute_script("return window.meshdiffReport.project(arguments[0], arguments[1])", on, loc["point"])
    mx, my = int(p["x"]), int(p["y"])
    check(img.getpixel((mx, my)) == (255, 0, 255), f"magenta marker drawn at ({mx}, {my}): {img.getpixel((mx, my))}")

    # A click on the marker shows the certified interval; a click on the surface, the value there.
    from selenium.webdriver.common.action_chains import ActionChains
    canvas = driver.find_element("id", "view")
    size = canvas.size

    def click(x, y):
        ActionChains(driver).move_to_element_with_offset(canvas, x - size["width"] // 2,
                                                         y - size["height"] // 2).click().perform()
        return driver.find_element("id", "probe").text

    text = click(mx, my)
    check("certified Hausdorff distance in [" in text, f"a click on the marker: {text!r}")
    sx, sy = next((x, y) for y in range(img.height // 3, img.height, 5) for x in range(0, img.width // 2, 5)
                  if on_sequential(img.getpixel((x, y))) and on_sequential(img.getpixel((x + 3, y + 3)))
                  and abs(x - mx) + abs(y - my) > 40)
    text = click(sx + 3, sy + 3)
    check("original vertex" in text and "distance =" in text, f"a click on the surface: {text!r}")

    # Roughness: another picture, on the diverging ramp (white at 0).
    driver.execute_script("window.meshdiffReport.setField('D_1')")
    img2 = frame()
    changed = sum(1 for a, b in zip(px, img2.getdata()) if a != b)
    check(changed > 0.05 * len(px), f"D_1 changes {changed / len(px):.0%} of the canvas")
    whiteish = sum(1 for c in img2.getdata() if c != (255, 255, 255) and min(c) > 200 and max(c) - min(c) < 40)
    check(whiteish > 100, f"the D_1 view has the diverging ramp's near-white ({whiteish} pixels)")
    driver.execute_script("window.meshdiffReport.setField('D_global')")
    check(frame() != img2, "D_global differs from D_1")

    # The screenshot for README.md: shaded, distance.
    driver.execute_script("window.meshdiffReport.setShading(true); window.meshdiffReport.setField('distance')")
    frame()
    shot = os.path.join(work, "html-report.png")
    driver.find_element("id", "view").screenshot(shot)
    if os.environ.get("MESHDIFF_UPDATE_SCREENSHOT") == "1":
        shutil.copy(shot, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "html-report.png"))

    # The page's vertex colours are the PLY map's, for the same colour range.
    open_page(ranged)
    for k, side in enumerate(["original", "processed"]):
        page = driver.execute_script(f"return Array.from(window.meshdiffReport.colors({k}, 'distance'))")
        page = [tuple(page[i:i + 3]) for i in range(0, len(page), 3)]
        ply = read_ply_colors(f"{maps}_{side}.ply")
        check(page == ply, f"{side}: the page's {len(page)} vertex colours are the PLY map's")
    # meshdiff profile --html: one mesh; its tables equal its JSON; H coloured as the --vertex-data map.
    phtml, pjs, pply = (os.path.join(work, n) for n in ("profile.html", "profile.json", "profile_vd.ply"))
    run("profile", os.path.join(data, "fandisk.ply"), "--levels", "1,2,5", "--html", phtml, "--json", pjs,
        "--vertex-data", pply)
    pjson = json.load(open(pjs))
    open_page(phtml)
    embedded = driver.execute_script("return JSON.parse(document.getElementById('meshdiff-report').textContent)")
    check(embedded == pjson, "profile: the embedded JSON equals the CLI's --json report")
    cells = driver.execute_script(
        "return [...document.querySelectorAll('td[data-key]')].map(td => [td.dataset.key, td.dataset.value || null])")
    cli_json = pjson
    bad = [(k, v) for k, v in cells if v is not None and float(v) != at(k)]
    check(len(cells) > 10 and not bad, f"profile: {len(cells)} table cells equal the JSON ({bad[:3]})")
    check(any(k == "sigma.2" for k, _ in cells) and any(k == "sigma_global" for k, _ in cells),
          "profile: the table shows sigma per level and global")
    page = driver.execute_script("return Array.from(window.meshdiffReport.colors(0, 'H'))")
    check([tuple(page[i:i + 3]) for i in range(0, len(page), 3)] == read_ply_colors(pply),
          "profile: the page's H colours are the --vertex-data map's")
    # Shaded: the flat parts of the fandisk (H near 0: white on the ramp) are grey, not the white background.
    driver.execute_script("window.meshdiffReport.setShading(true)")
    pimg = frame()
    pimg.save(os.path.join(work, "profile.png"))
    check(sum(1 for c in pimg.getdata() if c != (255, 255, 255)) > 0.05 * pimg.width * pimg.height,
          "profile: the mesh is drawn")
    # --measure corsini --html: the Corsini table (per level, global, multi-scale) equals the JSON.
    chtml, cjs = os.path.join(work, "corsini.html"), os.path.join(work, "corsini.json")
    run(A, B, "--measure", "corsini", "--levels", "1,2,3", "-n", "20000", "--html", chtml, "--json", cjs)
    cli_json = json.load(open(cjs))
    open_page(chtml)
    cells = driver.execute_script(
        "return [...document.querySelectorAll('td[data-key]')].map(td => [td.dataset.key, td.dataset.value || null])")
    bad = [(k, v) for k, v in cells if v is not None and float(v) != at(k)]
    ckeys = {k for k, _ in cells}
    check(not bad and {"corsini_distance.distance.2", "original.corsini.roughness.0", "processed.corsini.multiscale",
                       "corsini_distance.multiscale.distance", "corsini_distance.global.distance"} <= ckeys,
          f"corsini: the Corsini table's {len(cells)} cells equal the JSON ({bad[:3]}; {sorted(ckeys)[:5]})")
    logs = driver.get_log("browser")
    errors = [e for e in logs if e["level"] == "SEVERE"]
    check(not errors, f"no console error ({errors[:3]})")
finally:
    driver.quit()

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
