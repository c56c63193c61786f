#!/usr/bin/env python3
"""live_browser.py EXECUTABLE [SCREENSHOT.png]: the live view (--live) in a real headless Chromium.

Drives Debian's chromium through chromedriver (web_driver.py):
loads the page of chapter 06's executable, sees the image change from one pass to the next and the counters
go up, switches indirect light off with its checkbox and the depth with its field, sees the render start again
with them (the image and the counters change), and takes a screenshot, a PNG with more than one colour
(written to SCREENSHOT.png when given). Exit 77 (skipped) when chromium or chromedriver is not installed.
"""
import base64
import os
import struct
import sys
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from live_run import LiveRun, fail  # noqa: E402
from web_driver import WebDriver, browser_or_skip, start_chromedriver, wait_until  # noqa: E402

browser, driver = browser_or_skip()
exe = sys.argv[1]
screenshot_file = sys.argv[2] if len(sys.argv) > 2 else None


# What the page's image holds now: its URL (the frame) and a hash of its pixels, drawn into a canvas.
IMAGE = """
const img = document.getElementById('image');
if (!img.complete || img.naturalWidth === 0) return null;
const c = document.createElement('canvas');
c.width = img.naturalWidth; c.height = img.naturalHeight;
const g = c.getContext('2d'); g.drawImage(img, 0, 0);
const d = g.getImageData(0, 0, c.width, c.height).data;
let h = 0; for (let i = 0; i < d.length; i++) h = (Math.imul(h, 31) + d[i]) >>> 0;
return [img.src, h, c.width, c.height];
"""
COUNTER = "const r = document.getElementById('counter-%s'); return r ? r.cells[1].textContent : null;"
STATUS = "return document.getElementById('status').textContent;"


def png_has_content(png):
    """A PNG whose pixels are not all one colour (8-bit RGB or RGBA, as a screenshot is)."""
    if not png.startswith(b"\x89PNG\r\n\x1a\n"):
        return False
    at, idat, width, height, channels = 8, b"", 0, 0, 0
    while at < len(png):
        length, kind = struct.unpack(">I4s", png[at:at + 8])
        data = png[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", data[:10])
            channels = {2: 3, 6: 4}.get(colour, 0) if depth == 8 else 0
        elif kind == b"IDAT":
            idat += data
        at += 12 + length
    if width == 0 or height == 0 or channels == 0:
        return False
    raw = zlib.decompress(idat)
    stride = width * channels
    if len(raw) != (1 + stride) * height:
        return False
    # Undo each row's filter (PNG specification, section 9) to get its pixels.
    previous, colours = bytearray(stride), set()
    for y in range(height):
        kind, row = raw[y * (1 + stride)], bytearray(raw[y * (1 + stride) + 1:(y + 1) * (1 + stride)])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        colours.update(bytes(row[x:x + channels]) for x in range(0, stride, channels * 7))
        previous = row
    return len(colours) > 1


run = LiveRun(exe, "--width", "96", "--height", "64", "--spp", "4096", "--threads", "2", "--quiet")
chromedriver, chromedriver_port = start_chromedriver(driver)
web = None
try:
    started = time.time()
    web = WebDriver(chromedriver_port, browser)
    web.command("POST", "/url", {"url": "http://127.0.0.1:%d/" % run.port})
    first = wait_until("the image of a pass", lambda: web.script(IMAGE))
    spp_first = wait_until("the counters", lambda: web.script(COUNTER % "samples-per-pixel"))
    second = wait_until("the image of a later pass", lambda: (lambda i: i if i and i[0] != first[0] and i[1] != first[1] else None)(web.script(IMAGE)))
    spp_second = wait_until("the counters of a later pass",
                            lambda: (lambda c: c if c != spp_first else None)(web.script(COUNTER % "samples-per-pixel")))
    print("the image changed between passes (%s, then %s), samples per pixel %s, then %s"
          % (first[0].rsplit("=", 1)[1], second[0].rsplit("=", 1)[1], spp_first, spp_second))

    render = run.state()["render"]
    web.command("POST", "/element/%s/click" % web.element("#effect-indirect"))
    state = run.wait_for("the render without indirect light", lambda s: s["render"] > render)
    if "indirect" in state["simulated"]:
        fail("the checkbox did not switch indirect light off: %s" % state["simulated"])
    wait_until("the page to say so", lambda: "indirect" not in web.script(STATUS).split("simulated:")[1])
    render = state["render"]
    depth = web.element("#knob--max-depth")
    web.command("POST", "/element/%s/clear" % depth)
    web.command("POST", "/element/%s/value" % depth, {"text": "1\ue007"})  # then Enter
    state = run.wait_for("the render with depth 1", lambda s: s["render"] > render and s["frame"] > 0)
    if {k["name"]: k["value"] for k in state["knobs"]}["--max-depth"] != "1":
        fail("the field did not set --max-depth: %s" % state["knobs"])
    third = wait_until("the image of the new render",
                       lambda: (lambda i: i if i and i[1] not in (first[1], second[1]) else None)(web.script(IMAGE)))
    print("indirect light switched off and --max-depth 1 set from the page: render %d, image %s"
          % (state["render"], third[0].rsplit("=", 1)[1]))

    web.script("window.scrollTo(0, 0);")
    png = base64.b64decode(web.command("GET", "/screenshot"))
    if not png_has_content(png):
        fail("the screenshot is not a PNG with content (%d bytes)" % len(png))
    if screenshot_file:
        with open(screenshot_file, "wb") as out:
            out.write(png)
    print("screenshot: a PNG of %d bytes with content; in the browser for %.1f s" % (len(png), time.time() - started))
finally:
    if web:
        web.quit()  # the browser ends with its session, not with chromedriver
    chromedriver.terminate()
    chromedriver.wait(30)
status = run.interrupt()
if status != 130:
    fail("SIGINT: exit %d, expected 130" % status)
print("SIGINT: exit 130")
