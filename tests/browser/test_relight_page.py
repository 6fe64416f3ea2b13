#!/usr/bin/env python3
"""The relighting page of `ochre relight RENDER.exr --html DIR` (docs/lights.md, "Relighting page") in a real
browser: headless Chromium driven by Selenium opens the page from a file:// URL, moves a group's intensity
and another's colour temperature through DOM events, reads the canvas back (getImageData) and compares it
with the PNG that the command the page shows writes (`ochre relight ... --png`).

The page interpolates the display transform in a lattice (33^3 points over a log2 shaper) where the PNG
evaluates it per pixel, and holds the layers as half floats and a colour temperature as a few basis images:
an interpolated value may round to the next 8-bit level, so every channel must agree within 2 levels and on
average within 0.5 (measured: at most 1 level, mean 0.11 to 0.21, also with 12 % of the channels clipped).

Run by ctest (tests/CMakeLists.txt, test Browser.RelightPage):
  test_relight_page.py --ochre build/bin/ochre --source . --work build/tests/tmp/browser-relight
Exits 77 (ctest: skipped) when Selenium, Chromium or chromedriver is missing.
"""

import argparse
import os
import shlex
import shutil
import struct
import subprocess
import sys
import time
import unittest
import zlib

from test_html_report import require_browser, run_tests, start_driver

ARGS = None
DRIVER = None
TOLERANCE = 2  # levels of 8 bits, for every channel
MEAN_TOLERANCE = 0.5


def read_png(path):
    """(width, height, bytes of RGB rows): 8-bit RGB or RGBA PNG, not interlaced (what ochre writes)."""
    with open(path, "rb") as f:
        data = f.read()
    pos, chunks, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks.append(body)
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise AssertionError(f"{path}: unexpected PNG format {header}")
    channels = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(b"".join(chunks)), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[x] for x in range(stride) if channels == 3 or x % 4 != 3))
        previous = line
    return width, height, b"".join(rows)


def render(work):
    shutil.copy(os.path.join(ARGS.source, "tests", "browser", "relight_wall.json"), work)
    subprocess.run([ARGS.ochre, "render", "relight_wall.json", "-o", "render.exr", "-q", "--spectral-bins", "16"],
                   cwd=work, check=True)
    result = subprocess.run([ARGS.ochre, "relight", "render.exr", "--html", "page"], cwd=work,
                            capture_output=True, text=True, check=True)
    print(result.stderr.strip(), file=sys.stderr)


def open_page():
    DRIVER.get("file://" + os.path.join(ARGS.work, "page", "index.html"))
    deadline = time.time() + 20
    while DRIVER.execute_script("return document.body.dataset.ready") != "true":
        if time.time() > deadline:
            raise AssertionError("the page's script did not start")
        time.sleep(0.02)


def move(element_id, value):
    DRIVER.execute_script("const e = document.getElementById(arguments[0]); e.value = arguments[1];"
                          "e.dispatchEvent(new Event('input'));", element_id, str(value))


def canvas_rgb():
    pixels = DRIVER.execute_script(
        "const c = document.getElementById('image');"
        "return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data)")
    return bytes(v for i, v in enumerate(pixels) if i % 4 != 3)


class RelightPage(unittest.TestCase):
    def compare_with_command(self, expected_command, name):
        """The page's command is `expected_command`; run, its PNG matches the canvas."""
        command = DRIVER.find_element("id", "command").get_attribute("value")
        self.assertEqual(command, expected_command)
        words = shlex.split(command)
        words[words.index("relit.png")] = name + ".png"
        subprocess.run([ARGS.ochre] + words[1:] + ["-q"], cwd=ARGS.work, check=True)
        _, _, png = read_png(os.path.join(ARGS.work, name + ".png"))
        page = canvas_rgb()
        self.assertEqual(len(page), len(png))
        differences = [abs(a - b) for a, b in zip(page, png)]
        mean = sum(differences) / len(differences)
        print(f"  {name}: largest difference {max(differences)} levels, mean {mean:.3f}", file=sys.stderr)
        self.assertLessEqual(max(differences), TOLERANCE)
        self.assertLessEqual(mean, MEAN_TOLERANCE)

    def test_unchanged(self):
        open_page()
        self.compare_with_command("ochre relight render.exr --png relit.png", "unchanged")

    def test_half_intensity(self):
        open_page()
        move("scale-torch", 0.5)
        self.assertEqual(DRIVER.find_element("id", "scale-torch-value").text, "0.5")
        self.compare_with_command("ochre relight render.exr --group torch:scale=0.5 --png relit.png", "half")

    def test_half_intensity_and_a_colour_temperature(self):
        open_page()
        move("scale-torch", 0.5)
        move("cct-lamp", 6500)
        self.compare_with_command(
            "ochre relight render.exr --group torch:scale=0.5 --group lamp:cct=6500 --png relit.png", "cct")
        DRIVER.find_element("id", "cct-lamp-reset").click()
        DRIVER.find_element("id", "on-other").click()
        self.compare_with_command(
            "ochre relight render.exr --group torch:scale=0.5 --group other:off --png relit.png", "reset")

    def test_bright_enough_to_clip(self):
        open_page()
        move("scale-torch", 4)
        move("cct-torch", 10000)
        move("scale-lamp", 2.5)
        self.compare_with_command("ochre relight render.exr --group torch:scale=4,cct=10000 --group lamp:scale=2.5 "
                                  "--png relit.png", "clip")

    def test_no_colour_temperature_without_one_emission(self):
        DRIVER.get_log("browser")  # drop earlier messages
        open_page()
        DRIVER.find_element("id", "copy").click()  # the clipboard may refuse: the page falls back quietly
        self.assertEqual(DRIVER.find_elements("id", "cct-other"), [])
        self.assertEqual(len(DRIVER.find_elements("id", "cct-torch")), 1)
        self.assertEqual(DRIVER.find_element("id", "cct-torch").get_attribute("value"), "1700")
        self.assertEqual(DRIVER.find_element("id", "cct-torch-value").text, "unchanged (about 1700 K)")
        self.assertEqual([e["message"] for e in DRIVER.get_log("browser") if e["level"] == "SEVERE"], [])


def main():
    global ARGS, DRIVER
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ochre", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    ARGS = parser.parse_args()
    ARGS.work, ARGS.ochre = os.path.abspath(ARGS.work), os.path.abspath(ARGS.ochre)
    require_browser()
    shutil.rmtree(ARGS.work, ignore_errors=True)
    os.makedirs(ARGS.work)
    render(ARGS.work)
    DRIVER = start_driver()
    run_tests(DRIVER)


if __name__ == "__main__":
    main()
