#!/usr/bin/env python3
"""Load time and frame time of a meshdiff HTML report in headless chromium.

Usage: html_frames.py REPORT.html [--moves N] [--runs R]

Opens the page as tests/html_browser_test.py does (headless chromium with
SwiftShader's software WebGL, file://, network off, a 1200x1400 window),
then drags the view: a mousedown on the canvas, one mousemove of 4 pixels per
animation frame (OrbitControls rotates and the page redraws each frame), a
mouseup. Prints the page's size, the time from navigation to the first drawn
frame, the median and 90th percentile of the intervals between animation
frames during the drag (the frame time a user sees while rotating), the faces
drawn in the drag's frames and the time from the mouseup until the full
drawn mesh is on screen again. R runs (default 3) of N moves (default 20)."""
import argparse
import os
import shutil
import statistics
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

DRAG = """
const done = arguments[arguments.length - 1], moves = arguments[0];
const canvas = document.getElementById('view'), r = canvas.getBoundingClientRect(), st = window.meshdiffReport.state;
let x = r.left + r.width / 4, y = r.top + r.height / 2, n = 0;
const mouse = (type, target) => target.dispatchEvent(new MouseEvent(type, {clientX: x, clientY: y, button: 0,
  buttons: type === 'mouseup' ? 0 : 1, bubbles: true}));
const stamps = [], drawn = [];
mouse('mousedown', canvas);
function step(t) {
  stamps.push(t);
  drawn.push(st.drawnFaces === undefined ? null : st.drawnFaces);
  if (n++ < moves) {
    x += 4;
    mouse('mousemove', document);
    requestAnimationFrame(step);
    return;
  }
  mouse('mouseup', document);
  const up = performance.now();
  (function wait() {
    // Done when the page is back at rest: no coarse frame on screen and none to come (a page without the
    // coarse meshes, or before them, has neither field: its last drag frame is its full view).
    if (!st.interacting && st.lod !== 'coarse') {
      done({stamps, drawn, settle: performance.now() - up, lod: st.lod === undefined ? null : st.lod,
            full: st.drawnFaces === undefined ? null : st.drawnFaces});
    } else {
      setTimeout(wait, 10);
    }
  })();
}
requestAnimationFrame(step);
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("report")
    ap.add_argument("--moves", type=int, default=20)
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium")
    for flag in ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1200,1400",
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--force-device-scale-factor=1",
                 "--allow-file-access-from-files"]:
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    try:
        driver.set_page_load_timeout(300)
        driver.set_script_timeout(600)
        driver.execute_cdp_cmd("Network.enable", {})
        driver.execute_cdp_cmd("Network.emulateNetworkConditions",
                               {"offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
        t0 = time.time()
        driver.get("file://" + os.path.abspath(a.report))
        while not driver.execute_script("return !!(window.meshdiffReport && window.meshdiffReport.state.frames > 0)"):
            time.sleep(0.02)
        load = time.time() - t0
        print(f"page: {os.path.getsize(a.report) / 1e6:.1f} MB; loaded and first frame drawn in {load:.1f} s")
        driver.execute_script("document.getElementById('view').scrollIntoView()")
        time.sleep(1.0)
        for run in range(a.runs):
            r = driver.execute_async_script(DRAG, a.moves)
            gaps = [b - a for a, b in zip(r["stamps"], r["stamps"][1:])]
            drawn = sorted({d for d in r["drawn"][2:] if d is not None})
            print(f"run {run + 1}: {len(gaps)} frames while rotating, median {statistics.median(gaps):.0f} ms, "
                  f"p90 {sorted(gaps)[int(0.9 * (len(gaps) - 1))]:.0f} ms; faces drawn while rotating "
                  f"{drawn or 'n/a'}; full view ({r['full'] if r['full'] is not None else 'n/a'} faces) back "
                  f"{r['settle']:.0f} ms after the mouseup")
    finally:
        driver.quit()


if __name__ == "__main__":
    sys.exit(main())
