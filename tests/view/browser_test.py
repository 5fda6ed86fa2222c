#!/usr/bin/env python3
"""The page of `locus view` in a real browser (headless Chromium through Selenium): the first
frame arrives and is not blank; typing an equation changes the picture; a malformed equation
shows its error with the column; dragging turns the view; moving a parameter's slider changes
the surface. Exits 77 (skipped, ctest's SKIP_RETURN_CODE) when Chromium, chromedriver or
Selenium is missing.

Usage: tests/view/browser_test.py PATH/TO/locus [SCREENSHOT_DIR]
With SCREENSHOT_DIR (docs/images/view/ for the user guide) each step's screenshot is saved there.
"""
import os
import shutil
import subprocess
import sys
import time

locus = sys.argv[1]
shots = sys.argv[2] if len(sys.argv) > 2 else None
chromium = shutil.which("chromium") or shutil.which("chromium-browser")
driver_path = shutil.which("chromedriver")
try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
except ImportError:
    chromium = None
if not chromium or not driver_path:
    print("SKIPPED: the browser test needs chromium, chromium-driver and python3-selenium "
          "(scripts/install-deps installs them)")
    sys.exit(77)

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


EQUATION = "x^4+y^4+z^4-a*(x^2+y^2+z^2)+0.5"
SANITIZED = os.environ.get("LOCUS_SANITIZED") == "1"
server = subprocess.Popen([locus, "view", EQUATION, "--port", "0", "--timeout",
                           "800" if SANITIZED else "240"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
first_line = server.stdout.readline().strip()
check(first_line.startswith("serving on http://127.0.0.1:"), "first line: " + first_line)
url = first_line.split()[-1]

options = webdriver.ChromeOptions()
options.binary_location = chromium
for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
             "--window-size=960,640"):
    options.add_argument(flag)
browser = webdriver.Chrome(service=Service(driver_path), options=options)


def frames():
    return int(browser.execute_script("return document.body.dataset.frames || 0"))


# Seconds to wait for a full frame; the sanitized build (LOCUS_SANITIZED, set by ctest) renders
# 15-40 times slower.
FRAME_LIMIT = 150 if SANITIZED else 30


def wait_for_full_frame(after, what, limit=FRAME_LIMIT):
    deadline = time.time() + limit
    while time.time() < deadline:
        if frames() > after and browser.execute_script("return document.body.dataset.level") == "2":
            return True
        time.sleep(0.05)
    check(False, what + ": no full frame within %d s" % limit)
    return False


# A fingerprint of the picture on the page: pixels sampled through a canvas, and how many
# distinct colours they have.
FINGERPRINT = """
const img = document.getElementById('view');
const c = document.createElement('canvas'); c.width = 64; c.height = 64;
const g = c.getContext('2d'); g.drawImage(img, 0, 0, 64, 64);
const d = g.getImageData(0, 0, 64, 64).data;
const colours = new Set(); let sum = 0;
for (let i = 0; i < d.length; i += 4) { colours.add(d[i] * 65536 + d[i+1] * 256 + d[i+2]); sum += (i % 97) * d[i] + d[i+1]; }
return [colours.size, sum];
"""


def fingerprint():
    return tuple(browser.execute_script(FINGERPRINT))


def shot(name):
    if shots:
        os.makedirs(shots, exist_ok=True)
        browser.save_screenshot(os.path.join(shots, name))


try:
    browser.get(url)
    wait_for_full_frame(0, "the first frame")
    colours, first = fingerprint()
    check(colours > 20, "the first frame is not blank (%d colours)" % colours)
    check(browser.find_element(By.ID, "param-a") is not None, "a slider for the parameter a")
    shot("01-first-frame.png")

    equation = browser.find_element(By.ID, "equation")
    equation.clear()
    equation.send_keys("x^2 + y^2 + z^2 - 1")
    n = frames()
    browser.find_element(By.ID, "render").click()
    wait_for_full_frame(n, "the typed equation")
    check(fingerprint()[1] != first, "typing an equation changes the picture")
    shot("02-typed-equation.png")

    equation.clear()
    equation.send_keys("x^2 + * y")
    browser.find_element(By.ID, "render").click()
    time.sleep(0.5)
    error = browser.find_element(By.ID, "error")
    check(error.is_displayed() and "column 7" in error.text,
          "a malformed equation shows its column: " + error.text.splitlines()[0]
          if error.text else "a malformed equation shows an error")
    shot("03-parse-error.png")

    equation.clear()
    equation.send_keys(EQUATION)
    n = frames()
    browser.find_element(By.ID, "render").click()
    wait_for_full_frame(n, "back to the parametric quartic")
    before_drag = fingerprint()[1]
    camera_before = browser.execute_script("return window.locusState.camera.eye.slice()")
    n = frames()
    view = browser.find_element(By.ID, "view")
    ActionChains(browser).move_to_element(view).click_and_hold().move_by_offset(90, 30) \
        .pause(0.2).move_by_offset(40, 0).release().perform()
    wait_for_full_frame(n, "after the drag")
    camera_after = browser.execute_script("return window.locusState.camera.eye.slice()")
    check(camera_after != camera_before, "dragging turns the camera")
    check(fingerprint()[1] != before_drag, "dragging changes the picture")
    shot("04-dragged.png")

    # On a slow connection or server (each request held 600 ms by the browser's network
    # emulation), the previews of a drag are still on their way when the pointer rests: the
    # view must still end on a full frame, not on the quarter-resolution preview queued during
    # the drag (it did: the queued preview ran after the half-resolution frame, and the full
    # one was never asked for).
    browser.execute_cdp_cmd("Network.enable", {})
    browser.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": False, "latency": 600, "downloadThroughput": -1, "uploadThroughput": -1})
    n = frames()
    ActionChains(browser).move_to_element(view).click_and_hold().move_by_offset(-40, 10) \
        .pause(0.1).move_by_offset(-40, 10).pause(0.1).move_by_offset(-30, 0).release().perform()
    wait_for_full_frame(n, "after a drag on a slow connection")
    browser.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": False, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})

    before_slider = fingerprint()[1]
    n = frames()
    browser.execute_script("""
        const s = document.getElementById('param-a');
        s.value = 1.6; s.dispatchEvent(new Event('input'));""")
    wait_for_full_frame(n, "after the slider")
    check(fingerprint()[1] != before_slider, "moving the slider changes the surface")
    shot("05-slider.png")

    # A value typed into the parameter's box, past the slider's range, widens the range.
    value = browser.find_element(By.ID, "value-a")
    value.clear()
    value.send_keys("2.5\n")
    n = frames()
    browser.execute_script("document.getElementById('value-a').dispatchEvent(new Event('change'))")
    wait_for_full_frame(n, "after typing a value")
    slider_max = browser.execute_script("return document.getElementById('param-a').max")
    check(float(slider_max) >= 2.5, "a typed value widens the slider's range (max %s)" % slider_max)

    # A double-click on the surface centres the view there.
    target_before = browser.execute_script("return window.locusState.camera.target.slice()")
    n = frames()
    # A pixel of the surface, nearest the centre: one whose colour is not the corner's.
    dx, dy = browser.execute_script("""
        const img = document.getElementById('view');
        const c = document.createElement('canvas'); c.width = 64; c.height = 64;
        const g = c.getContext('2d'); g.drawImage(img, 0, 0, 64, 64);
        const d = g.getImageData(0, 0, 64, 64).data;
        const bg = [d[0], d[1], d[2]];
        let best = null;
        for (let y = 0; y < 64; ++y) for (let x = 0; x < 64; ++x) {
            const i = 4 * (64 * y + x);
            const far = Math.abs(d[i] - bg[0]) + Math.abs(d[i+1] - bg[1]) + Math.abs(d[i+2] - bg[2]);
            const r = (x - 32) ** 2 + (y - 32) ** 2;
            if (far > 60 && (best === null || r < best[2])) best = [x, y, r];
        }
        const size = img.getBoundingClientRect();
        return best ? [(best[0] + 0.5) / 64 * size.width - size.width / 2,
                       (best[1] + 0.5) / 64 * size.height - size.height / 2] : [0, 0];""")
    ActionChains(browser).move_to_element_with_offset(view, int(dx), int(dy)).double_click().perform()
    wait_for_full_frame(n, "after the double-click")
    target_after = browser.execute_script("return window.locusState.camera.target.slice()")
    check(target_after != target_before, "a double-click on the surface re-centres the view")
finally:
    browser.quit()
    server.terminate()
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.kill()
        failures.append("the server did not stop on SIGTERM")
    check(server.returncode == 0, "the server stops cleanly on SIGTERM (exit %s)" % server.returncode)

print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
