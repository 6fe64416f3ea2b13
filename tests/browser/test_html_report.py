#!/usr/bin/env python3
"""The HTML report of ochre-regress (docs/tools.md, "HTML report") in a real browser: headless Chromium
driven by Selenium opens the report from a file:// URL and checks that every image loads, that nothing
is requested from elsewhere, that the slider, the flip toggle, the zoom and the pixel readout respond to
simulated input (read back from the DOM), and the Stokes readout and the spectrum of a polarized,
spectral scene.

Run by ctest (tests/CMakeLists.txt, test Browser.HtmlReport):
  test_html_report.py --regress build/bin/ochre-regress --source . --work build/tests/tmp/browser
Exits 77 (ctest: skipped) with a message when Selenium, Chromium or chromedriver is missing
(Debian: chromium chromium-driver python3-selenium, installed by tools/setup.sh).
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time
import unittest

SKIP = 77

ARGS = None
REPORT = None  # the report directory
WORST = None  # (x, y, z, p) of the failing scene, from the command line's message
DRIVER = None


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(SKIP)


def chromium_binary():
    for candidate in ("/usr/lib/chromium/chromium", shutil.which("chromium"), shutil.which("chromium-browser")):
        if candidate and os.path.exists(candidate):
            return candidate
    return None


def require_browser():
    """Exits 77 (skipped) unless Selenium, Chromium and chromedriver are all there."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        skip(f"no Selenium for {sys.executable} (Debian: python3-selenium)")
    if not chromium_binary():
        skip("no Chromium (Debian: chromium)")
    if not shutil.which("chromedriver"):
        skip("no chromedriver (Debian: chromium-driver)")


def run_tests(driver):
    """Runs the test cases of the script started (unittest), quits `driver`, exits 0 or 1."""
    try:
        result = unittest.main(argv=[sys.argv[0], "-v"], exit=False).result
    finally:
        driver.quit()
    sys.exit(0 if result.wasSuccessful() else 1)


def make_suite(work):
    """work/suite: lambert_environment made brighter (fails against the committed reference), spot_light
    (passes) and the polarized spectral scene of this folder with a reference made now."""
    suite = os.path.join(work, "suite")
    os.makedirs(os.path.join(suite, "references"))
    regression = os.path.join(ARGS.source, "tests", "regression")
    for name in ("lambert_environment", "spot_light"):
        shutil.copy(os.path.join(regression, name + ".json"), suite)
        shutil.copy(os.path.join(regression, "references", name + ".exr"), os.path.join(suite, "references"))
    scene = os.path.join(suite, "lambert_environment.json")
    with open(scene) as f:
        text = f.read()
    with open(scene, "w") as f:
        f.write(text.replace('"color": 0.5', '"color": 0.55'))
    shutil.copy(os.path.join(ARGS.source, "tests", "browser", "polarized_spectral.json"), suite)
    subprocess.run([ARGS.regress, suite, "--update", "--scene", "polarized_spectral", "--reference-spp", "64"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(work, "earlier.xml"), "w") as f:
        f.write('<testsuite timestamp="2024-01-02T03:04:05Z"><testcase name="lambert_environment" time="0.5"/>'
                '<testcase name="spot_light" time="0.25"/></testsuite>\n')
    return suite


def write_report(work):
    global REPORT, WORST
    suite = make_suite(work)
    REPORT = os.path.join(work, "report")
    result = subprocess.run([ARGS.regress, suite, "--html", REPORT, "--history", os.path.join(work, "earlier.xml"),
                             "--output-dir", os.path.join(work, "out")], capture_output=True, text=True)
    if result.returncode != 4:  # a scene failed (docs/cli.md, "Exit codes")
        raise RuntimeError(f"ochre-regress exited {result.returncode}:\n{result.stdout}{result.stderr}")
    m = re.search(r"worst p = (\S+) at x=(\d+) y=(\d+) \(z = (-?[\d.]+)\)", result.stderr)
    WORST = (int(m.group(2)), int(m.group(3)), float(m.group(4)), float(m.group(1)))
    print(result.stdout.strip().splitlines()[-1])


def start_driver():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--window-size=1280,1800", "--force-device-scale-factor=1"):
        options.add_argument(argument)
    options.binary_location = chromium_binary()
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)


def url(page, fragment=""):
    return "file://" + os.path.join(REPORT, page) + fragment


def open_page(page, fragment=""):
    DRIVER.get(url(page, fragment))
    deadline = time.time() + 10
    while DRIVER.execute_script("return document.body.dataset.ready") != "true":
        if time.time() > deadline:
            raise AssertionError(f"{page}: report.js did not start")
        time.sleep(0.02)


def wait_for_images():
    """Waits until every <img> has finished (loaded or failed); returns those that did not load."""
    script = "return Array.from(document.images).filter(i => !i.complete).length"
    deadline = time.time() + 10
    while DRIVER.execute_script(script) > 0 and time.time() < deadline:
        time.sleep(0.02)
    return DRIVER.execute_script(
        "return Array.from(document.images).filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.src)")


def text(element_id):
    return DRIVER.find_element("id", element_id).text


def requested_urls():
    """The URLs the browser requested since the last call (Chrome DevTools protocol events)."""
    urls = []
    for entry in DRIVER.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            urls.append(message["params"]["request"]["url"])
    return urls


def severe_console_messages():
    return [entry["message"] for entry in DRIVER.get_log("browser") if entry["level"] == "SEVERE"]


class TimedTest(unittest.TestCase):
    def setUp(self):
        self.start = time.time()
        DRIVER.get_log("browser")  # drop earlier messages
        DRIVER.get_log("performance")

    def tearDown(self):
        print(f"  {self.id().split('.')[-1]}: {time.time() - self.start:.2f} s", file=sys.stderr)


class IndexPage(TimedTest):
    def test_rows_images_history_and_filter(self):
        open_page("index.html")
        self.assertEqual(wait_for_images(), [])
        rows = DRIVER.find_elements("css selector", "table.scenes tbody tr")
        self.assertEqual([r.get_attribute("data-scene") for r in rows],
                         ["lambert_environment", "polarized_spectral", "spot_light"])
        words = [r.find_element("css selector", ".status .word").text for r in rows]
        self.assertEqual(words, ["FAIL", "PASS", "PASS"])
        # History: the earlier run and this one, as words for screen readers too.
        history = rows[0].find_elements("css selector", "ol.history li")
        self.assertEqual(len(history), 2)
        self.assertEqual(history[0].get_attribute("title"), "2024-01-02T03:04:05Z: PASS, 0.50 s")
        self.assertTrue(history[1].get_attribute("title").startswith("this run: FAIL"))
        DRIVER.find_element("id", "failed-only").click()
        self.assertEqual([r.is_displayed() for r in rows], [True, False, False])
        self.assertEqual(severe_console_messages(), [])


class ScenePages(TimedTest):
    def test_every_image_loads_and_nothing_is_requested_from_elsewhere(self):
        pages = sorted(p for p in os.listdir(REPORT) if p.startswith("scene-") and p.endswith(".html"))
        self.assertEqual(len(pages), 3)
        prefix = "file://" + REPORT + "/"
        for page in ["index.html"] + pages:
            open_page(page)
            self.assertEqual(wait_for_images(), [], page)
            if page != "index.html":
                self.assertEqual(len(DRIVER.find_elements("css selector", ".viewport canvas")), 5, page)
            requests = requested_urls()
            self.assertIn(url(page), requests)  # the log works: the page itself is in it
            for name in requests:
                self.assertTrue(name.startswith(prefix), f"{page} requested {name}")
            for link in DRIVER.execute_script(
                    "return Array.from(document.querySelectorAll('[src],[href]')).map(e => e.src || e.href)"):
                self.assertTrue(link.startswith(prefix), f"{page} links to {link}")
            self.assertEqual(severe_console_messages(), [], page)

    def compare_screenshot(self):
        return DRIVER.find_element("css selector", ".viewport.compare canvas").screenshot_as_png

    def test_slider_and_flip(self):
        from selenium.webdriver.common.keys import Keys

        open_page("scene-lambert_environment.html")
        DRIVER.find_element("css selector", "input[name=mode][value=slider]").click()
        self.assertFalse(DRIVER.find_element("id", "compare").get_attribute("hidden"))
        self.assertFalse(DRIVER.find_element("id", "side-by-side").is_displayed())
        split = DRIVER.find_element("id", "split")
        split.send_keys(Keys.HOME)
        self.assertEqual(text("split-value"), "0 %")
        all_new = self.compare_screenshot()
        split.send_keys(Keys.END)
        self.assertEqual(text("split-value"), "100 %")
        all_reference = self.compare_screenshot()
        split.send_keys(Keys.ARROW_LEFT)
        self.assertEqual(text("split-value"), "99 %")
        canvas = DRIVER.find_element("css selector", ".viewport.compare canvas")
        self.assertEqual(canvas.get_attribute("data-split"), "0.99")
        self.assertNotEqual(all_new, all_reference)

        # Flip shows one image whole: the same pixels as the slider at either end.
        DRIVER.find_element("css selector", "input[name=mode][value=flip]").click()
        self.assertFalse(DRIVER.find_element("id", "split").is_displayed())
        self.assertEqual(text("flip-state"), "Reference")
        self.assertEqual(self.compare_screenshot(), all_reference)
        DRIVER.find_element("id", "flip").click()
        self.assertEqual(text("flip-state"), "New render")
        self.assertEqual(DRIVER.find_element("id", "flip").get_attribute("aria-pressed"), "true")
        self.assertEqual(self.compare_screenshot(), all_new)
        DRIVER.find_element("tag name", "body").send_keys("f")  # the keyboard shortcut
        self.assertEqual(text("flip-state"), "Reference")

    def hover_pixel(self, view, x, y):
        from selenium.webdriver.common.action_chains import ActionChains

        canvas = DRIVER.find_element("css selector", f"canvas[data-view={view}]")
        scale = float(canvas.get_attribute("data-scale"))
        data = DRIVER.execute_script("return [ochreSceneData.width, ochreSceneData.height]")
        # Offsets from the canvas centre, which shows the image centre at the fitted zoom.
        ActionChains(DRIVER).move_to_element_with_offset(
            canvas, round((x + 0.5 - data[0] / 2) * scale), round((y + 0.5 - data[1] / 2) * scale)).perform()
        return canvas

    def position(self):
        element = DRIVER.find_element("id", "ro-position")
        return int(element.get_attribute("data-x")), int(element.get_attribute("data-y"))

    def test_pixel_readout_zoom_and_worst_pixel(self):
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.keys import Keys

        x, y, z, p = WORST
        open_page("scene-lambert_environment.html")
        canvas = self.hover_pixel("new", x, y)
        self.assertEqual(self.position(), (x, y))
        self.assertTrue(text("ro-position").startswith("Pixel: x = "))
        # The readout decodes the same z and p as the command line printed.
        self.assertAlmostEqual(float(text("ro-z")), z, delta=0.006)
        self.assertAlmostEqual(float(text("ro-p")) / p, 1.0, delta=0.01)
        self.assertEqual(text("ro-failing"), "Yes")
        for side in ("reference", "new"):
            rgb = [float(v) for v in text(f"ro-{side}-rgb").split(", ")]
            xyz = [float(v) for v in text(f"ro-{side}-xyz").split(", ")]
            self.assertEqual(len(rgb), 3)
            # Y of Rec.709 RGB (the scene's working space).
            self.assertAlmostEqual(xyz[1], 0.2126729 * rgb[0] + 0.7151522 * rgb[1] + 0.072175 * rgb[2], delta=2e-3)
        # The brighter albedo: the new render is brighter there.
        self.assertGreater(float(text("ro-new-xyz").split(", ")[1]), float(text("ro-reference-xyz").split(", ")[1]))

        # Click pins the pixel; the arrow keys move it; hovering elsewhere does not change it.
        ActionChains(DRIVER).click().perform()
        self.assertTrue(text("ro-position").startswith("Pinned pixel"))
        canvas.send_keys(Keys.ARROW_RIGHT)
        self.assertEqual(self.position(), (x + 1, y))
        self.hover_pixel("reference", 0, 0)
        self.assertEqual(self.position(), (x + 1, y))
        canvas.send_keys(Keys.ESCAPE)
        self.hover_pixel("z", 3, 4)
        self.assertEqual(self.position(), (3, 4))

        # Zoom to single pixels.
        fitted = float(canvas.get_attribute("data-scale"))
        for _ in range(3):
            DRIVER.find_element("id", "zoom-in").click()
        self.assertAlmostEqual(float(canvas.get_attribute("data-scale")), 8 * fitted, delta=1e-6)
        self.assertRegex(text("zoom-level"), r"px/px$")
        DRIVER.find_element("id", "zoom-fit").click()
        self.assertEqual(text("zoom-level"), "fit")
        DRIVER.find_element("id", "worst-pixel").click()
        self.assertEqual(self.position(), (x, y))
        self.assertGreaterEqual(float(canvas.get_attribute("data-scale")), 24 - 1e-6)

    def test_stokes_readout_and_spectrum(self):
        open_page("scene-polarized_spectral.html")
        self.assertTrue(DRIVER.find_element("id", "spectrum-section").get_attribute("hidden"))
        self.hover_pixel("new", 12, 5)
        self.assertEqual(self.position(), (12, 5))
        for side in ("reference", "new"):
            stokes = [float(v) for v in text(f"ro-{side}-stokes").split(", ")]
            self.assertEqual(len(stokes), 4)
            dolp = float(text(f"ro-{side}-dolp"))
            self.assertAlmostEqual(dolp, (stokes[1] ** 2 + stokes[2] ** 2) ** 0.5 / stokes[0], delta=2e-3)
            self.assertTrue(0.0 <= dolp <= 1.0)
            self.assertTrue(-90.0 <= float(text(f"ro-{side}-aolp")) <= 90.0)
        self.assertFalse(DRIVER.find_element("id", "spectrum-section").get_attribute("hidden"))
        self.assertEqual(len(DRIVER.find_elements("css selector", "#spectrum circle.point-new")), 8)
        self.assertEqual(len(DRIVER.find_elements("css selector", "#spectrum rect.point-reference")), 8)
        self.assertEqual(len(DRIVER.find_elements("css selector", "#spectrum polyline")), 2)
        rows = DRIVER.execute_script("return document.querySelectorAll('#spectrum-table tbody tr').length")
        self.assertEqual(rows, 8)
        # A scene without Stokes layers says so instead of showing numbers.
        open_page("scene-spot_light.html")
        self.assertEqual(DRIVER.find_elements("id", "ro-new-stokes"), [])
        self.assertTrue(DRIVER.find_element("id", "spectrum-section").get_attribute("hidden"))


def main():
    global ARGS, DRIVER
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--regress", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    ARGS = parser.parse_args()
    require_browser()
    shutil.rmtree(ARGS.work, ignore_errors=True)
    os.makedirs(ARGS.work)
    start = time.time()
    write_report(ARGS.work)
    print(f"report written in {time.time() - start:.2f} s", file=sys.stderr)
    start = time.time()
    DRIVER = start_driver()
    print(f"Chromium started in {time.time() - start:.2f} s", file=sys.stderr)
    run_tests(DRIVER)


if __name__ == "__main__":
    main()
