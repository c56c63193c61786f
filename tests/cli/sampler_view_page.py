#!/usr/bin/env python3
"""sampler_view_page.py http|browser SAMPLER_VIEW [SCREENSHOT.png]: the sampler view's server and page.

http: the page and /samplers are served; /sample answers a right sampler with its histogram, density and a
passing verdict; bad queries (an unknown sampler, a value out of range, an unknown parameter) get 400 and one
line, and the server still answers after them; another Host is refused (403); a bad --port and a port in use
exit 2 with one line; SIGINT ends it, exit 130, nothing written.
browser: in a headless Chromium (web_driver.py; exit 77, skipped, without chromium and chromedriver), the page
draws the first sampler and says it passes, then a sampler picked from the list with its parameter set (its
heat maps hold more than one colour), refuses a value out of range in words, and draws a sampler of distances.
"""
import base64
import json
import os
import socket
import subprocess
import sys
from urllib.parse import urlencode

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from live_run import LiveRun, fail  # noqa: E402

mode, exe = sys.argv[1], sys.argv[2]
screenshot = sys.argv[3] if len(sys.argv) > 3 else None  # browser: the page as a PNG


def sample(run, **query):
    status, body = run.request("GET", "/sample?" + urlencode(query))
    return status, body.decode()


def check_http():
    run = LiveRun(exe, serve=())
    status, page = run.request("GET", "/")
    if status != 200 or b"<title>sampler view</title>" not in page:
        fail("/: status %d, not the page" % status)
    status, body = run.request("GET", "/samplers")
    names = [s["name"] for s in json.loads(body)["samplers"]] if status == 200 else []
    if "power_cosine" not in names or "henyey_greenstein" not in names:
        fail("/samplers: status %d, %s" % (status, names))
    status, body = sample(run, name="cosine_hemisphere", samples=100000)
    answer = json.loads(body) if status == 200 else {}
    if answer.get("problems") != [] or len(answer.get("observed", [])) != 48 * 96 or answer["p_value"] <= 0.01:
        fail("/sample cosine_hemisphere: status %d, %s" % (status, body[:300]))
    print("served: the page, %d samplers, cosine_hemisphere passes (p = %.3g)" % (len(names), answer["p_value"]))
    for query, words in [({"name": "nope"}, "unknown sampler"),
                         ({"name": "power_cosine", "exponent": "500"}, "must be in [0, 200]"),
                         ({"name": "power_cosine", "e": "6"}, "no parameter \"e\""),
                         ({"name": "power_cosine", "exponent": "1\x00"}, "must be a number")]:
        status, body = sample(run, **query)
        if status != 400 or words not in body or body.count("\n") != 1:
            fail("/sample %s: status %d, %r; expected 400 and one line with %r" % (query, status, body, words))
        print("refused, 400: " + body.strip())
    status, _ = run.request("GET", "/samplers", {"Host": "evil.example:%d" % run.port})
    if status != 403:
        fail("another Host: status %d, expected 403" % status)
    for flags, words in [(["--port", "-5"], "--port"), (["--port", str(run.port)], "cannot listen")]:
        refused = subprocess.run([exe, *flags], capture_output=True, text=True, timeout=60)
        lines = refused.stderr.strip().splitlines()
        if refused.returncode != 2 or len(lines) != 1 or words not in lines[0]:
            fail("%s: exit %d, stderr %r" % (flags, refused.returncode, refused.stderr))
        print("%s: exit 2, %s" % (" ".join(flags), lines[0]))
    status = run.interrupt()
    if status != 130 or run.files_written():
        fail("SIGINT: exit %d, files %s" % (status, run.files_written()))
    with socket.socket() as s:
        if s.connect_ex(("127.0.0.1", run.port)) == 0:
            fail("the port is still open after SIGINT")
    print("SIGINT: exit 130, nothing written, the port closed")


VERDICT = "const v = document.getElementById('verdict'); return [v.dataset.verdict || '', v.textContent];"
# The distinct colours of a canvas's pixels, up to 50.
COLOURS = """
const c = document.getElementById(arguments[0]), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
const seen = new Set();
for (let i = 0; i < d.length && seen.size < 50; i += 4) seen.add(d[i] + ',' + d[i + 1] + ',' + d[i + 2]);
return seen.size;
"""


def check_browser():
    from web_driver import WebDriver, browser_or_skip, start_chromedriver, wait_until
    browser, driver = browser_or_skip()
    run = LiveRun(exe, serve=())
    chromedriver, chromedriver_port = start_chromedriver(driver)
    web = None

    def verdict(starting):
        found = wait_until("a verdict starting %r" % starting,
                           lambda: (lambda v: v if v[1].startswith(starting) else None)(web.script(VERDICT)), 120)
        print("the page says: " + found[1])
        return found

    def set_field(css, text):
        field = web.element(css)
        web.command("POST", "/element/%s/clear" % field)
        web.command("POST", "/element/%s/value" % field, {"text": text})

    try:
        web = WebDriver(chromedriver_port, browser)
        web.command("POST", "/url", {"url": "http://127.0.0.1:%d/" % run.port})
        if verdict("uniform_hemisphere ")[0] != "pass":
            fail("the first sampler does not pass")
        set_field("#samples", "200000")
        web.command("POST", "/element/%s/click" % web.element("#sampler option[value=power_cosine]"))
        verdict("power_cosine passes")
        for canvas in ("histogram", "density"):
            colours = web.command("POST", "/execute/sync", {"script": COLOURS, "args": [canvas]})
            if colours < 10:
                fail("the %s map has %d colours" % (canvas, colours))
        print("both heat maps drawn")
        if screenshot:
            with open(screenshot, "wb") as out:
                out.write(base64.b64decode(web.command("GET", "/screenshot")))
        set_field("#param-exponent", "500")
        web.command("POST", "/element/%s/click" % web.element("#draw"))
        refused = verdict("refused (400)")
        if "exponent: must be in [0, 200], got 500" not in refused[1]:
            fail("the refusal does not say what is wrong: " + refused[1])
        set_field("#param-exponent", "48")
        web.command("POST", "/element/%s/click" % web.element("#draw"))
        if verdict("power_cosine ")[0] != "pass":
            fail("power_cosine with exponent 48 does not pass")
        web.command("POST", "/element/%s/click" % web.element("#sampler option[value=equiangular]"))
        if verdict("equiangular ")[0] != "pass":
            fail("equiangular distances do not pass")
        if screenshot:
            with open(screenshot.replace(".png", "-segment.png"), "wb") as out:
                out.write(base64.b64decode(web.command("GET", "/screenshot")))
    finally:
        if web:
            web.quit()
        chromedriver.terminate()
        chromedriver.wait(30)
    if run.interrupt() != 130:
        fail("SIGINT: not exit 130")


check_http() if mode == "http" else check_browser()
