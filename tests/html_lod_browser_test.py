#!/usr/bin/env python3
"""The HTML report's coarse mesh while the camera moves, in a real browser.

Headless Debian chromium driven by selenium (as html_browser_test.py) opens a
report of the bundled bunnies drawn with a small face budget and, with the
page's interaction budget lowered to 300 faces per mesh, checks that
  - each mesh has a coarse version of at most that many faces, whose vertex
    values are the largest-magnitude value of its cluster's vertices and whose
    colours are the colour map's for them;
  - while a mouse drag rotates the view, the coarse meshes are drawn (the
    page's drawn-face counter and the canvas's data-lod), in both viewports
    (one shared camera), and the full drawn meshes once the drag ends;
  - a wheel tick zooms with the coarse meshes and the full ones come back;
  - afterwards the Hausdorff marker is still drawn at the reported point, a
    click on the surface still probes the drawn mesh, and no console error.
Usage: html_lod_browser_test.py MESHDIFF DATA_DIR WORK_DIR
Exit 77 (a skip for ctest) only when chromium, chromedriver or selenium is
missing, and then 1 with MESHDIFF_REQUIRE_BROWSER=1."""
import io
import json
import math
import os
import shutil
import subprocess
import sys
import time

SKIP = 1 if os.environ.get("MESHDIFF_REQUIRE_BROWSER") == "1" else 77
CHROMIUM = shutil.which("chromium")
DRIVER = "/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else shutil.which("chromedriver")
try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
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
COARSE = 300
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


html, js = os.path.join(work, "lod.html"), os.path.join(work, "lod.json")
r = subprocess.run([cli, A, B, "--html", html, "--json", js, "--html-face-budget", "1000"], capture_output=True,
                   text=True)
if r.returncode != 0:
    sys.exit(f"meshdiff failed ({r.returncode}): {r.stderr}")
cli_json = json.load(open(js))

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
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions",
                           {"offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
    driver.get("file://" + os.path.abspath(html))

    def js_(code, *args):
        return driver.execute_script(code, *args)

    def wait(cond, what, timeout=20.0):
        t0 = time.time()
        while time.time() - t0 < timeout:
            if js_("return " + cond):
                return True
        check(False, f"{what} (waited {timeout} s for {cond})")
        return False

    wait("!!(window.meshdiffReport && window.meshdiffReport.state.frames > 0)", "the page draws")
    M = "window.meshdiffReport"
    faces = js_(f"return {M}.view.meshes.map(m => m.faces)")
    check(js_(f"return {M}.state.lod") == "full" and js_(f"return {M}.state.drawnFaces") == sum(faces),
          f"at rest the drawn meshes are drawn: {faces} faces")
    check(js_(f"return [{M}.coarseFaces(0), {M}.coarseFaces(1)]") == [None, None],
          "no coarse mesh below the page's interaction budget")
    check(not driver.find_elements("id", "lod-note"), "no interaction note for small meshes")

    js_(f"{M}.setInteractionFaces({COARSE})")
    coarse = js_(f"return [{M}.coarseFaces(0), {M}.coarseFaces(1)]")
    check(all(c is not None and 50 <= c <= COARSE for c in coarse), f"coarse meshes of {coarse} faces (<= {COARSE})")

    # The coarse colours: per cluster the value of largest magnitude of its vertices, in the colour map.
    for k in range(2):
        values = js_(f"return Array.from({M}.values({k}, 'distance'))")
        cluster = js_(f"return Array.from({M}.coarseCluster({k}))")
        cvalues = js_(f"return Array.from({M}.coarseValues({k}, 'distance'))")
        ccolors = js_(f"return Array.from({M}.coarseColors({k}, 'distance'))")
        expect = [None] * len(cvalues)
        for v, c in zip(values, cluster):
            if v is not None and (expect[c] is None or abs(v) > abs(expect[c])):
                expect[c] = v
        check(expect == cvalues, f"mesh {k}: the {len(cvalues)} coarse values are their clusters' largest")
        want = js_(f"return arguments[0].map(v => {M}.colorOf('distance', v === null ? NaN : v))", cvalues)
        check([c for rgb in want for c in rgb] == ccolors, f"mesh {k}: the coarse colours are the colour map's")

    # A drag: the coarse meshes while the button is held and the view turns, in both viewports; the full ones after.
    canvas = driver.find_element("id", "view")
    driver.execute_script("arguments[0].scrollIntoView()", canvas)
    n = js_(f"return {M}.state.frames")
    ActionChains(driver).move_to_element_with_offset(canvas, -200, 0).click_and_hold().move_by_offset(40, 0) \
        .move_by_offset(40, 10).perform()
    wait(f"{M}.state.frames > {n}", "a frame drawn while dragging")
    check(js_(f"return {M}.state.lod") == "coarse" and js_(f"return {M}.state.drawnFaces") == sum(coarse) and
          canvas.get_attribute("data-lod") == "coarse" and canvas.get_attribute("data-drawn-faces") == str(sum(coarse)),
          f"while dragging: coarse meshes drawn ({js_(f'return {M}.state.drawnFaces')} faces, both views)")
    ActionChains(driver).move_by_offset(30, 0).release().perform()
    wait(f"{M}.state.lod === 'full' && {M}.state.drawnFaces === {sum(faces)}", "the full meshes after the drag")
    check(canvas.get_attribute("data-lod") == "full" and canvas.get_attribute("data-drawn-faces") == str(sum(faces)),
          f"after the drag: the full drawn meshes ({sum(faces)} faces)")

    # A wheel tick (OrbitControls starts and ends an interaction per tick): coarse, then full again.
    n = js_(f"return {M}.state.frames")
    js_("arguments[0].dispatchEvent(new WheelEvent('wheel', {deltaY: -100, clientX: 300, clientY: 300, bubbles: true,"
        " cancelable: true}))", canvas)
    wait(f"{M}.state.frames > {n}", "a frame drawn after the wheel")
    check(js_(f"return {M}.state.lod") == "coarse", "a wheel tick draws the coarse meshes")
    wait(f"{M}.state.lod === 'full' && {M}.state.drawnFaces === {sum(faces)}", "the full meshes after the wheel")

    # The view after the interaction: the marker where the Hausdorff distance is attained, the probe on the mesh.
    h = cli_json["surface_distance"]["hausdorff"]
    loc = cli_json["surface_distance"][h["attained"]]["hausdorff"]["location"]
    on = 0 if h["attained"] == "forward" else 1
    n = js_(f"return {M}.state.frames")
    js_(f"{M}.setShading(false)")
    wait(f"{M}.state.frames > {n}", "a frame drawn")
    img = Image.open(io.BytesIO(canvas.screenshot_as_png)).convert("RGB")
    p = js_(f"return {M}.project(arguments[0], arguments[1])", on, loc["point"])
    px = img.getpixel((int(p["x"]), int(p["y"])))
    check(px == (255, 0, 255), f"the Hausdorff marker is drawn at the reported point after the interaction: {px}")
    check(js_(f"return {M}.state.lod") == "full", "still the full meshes")
    size = canvas.size
    probe = ""
    for y in range(size["height"] // 3, size["height"], 7):
        for x in range(20, size["width"] // 2, 7):
            c = img.getpixel((x, y))
            if c != (255, 255, 255) and c != (255, 0, 255) and abs(x - p["x"]) + abs(y - p["y"]) > 40:
                ActionChains(driver).move_to_element_with_offset(canvas, x - size["width"] // 2,
                                                                 y - size["height"] // 2).click().perform()
                probe = driver.find_element("id", "probe").text
                break
        if probe:
            break
    check("original (reduced) cluster" in probe and "distance =" in probe, f"a click probes the drawn mesh: {probe!r}")
    errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
    check(not errors, f"no console error ({errors[:3]})")
finally:
    driver.quit()

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
