"""Headless Chromium through chromedriver, for the browser tests of the live view (live_browser.py) and the
sampler view (sampler_view_browser.py): W3C WebDriver over plain HTTP, spoken with urllib."""
import json
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request

from live_run import fail


def browser_or_skip():
    """(chromium, chromedriver); exit 77 (skipped) when either is not installed."""
    browser = next(filter(None, map(shutil.which, ("chromium", "chromium-browser"))), None)
    driver = shutil.which("chromedriver")
    if not browser or not driver:
        print("SKIP: needs chromium and chromedriver (Debian: chromium chromium-driver)")
        sys.exit(77)
    return browser, driver


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_until(what, probe, seconds=60):
    deadline = time.time() + seconds
    while time.time() < deadline:
        value = probe()
        if value:
            return value
        time.sleep(0.05)
    fail("waited %g s for %s" % (seconds, what))


def start_chromedriver(driver):
    """chromedriver on a free port, once it listens: (process, port)."""
    port = free_port()
    process = subprocess.Popen([driver, "--port=%d" % port], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wait_until("chromedriver", lambda: socket.socket().connect_ex(("127.0.0.1", port)) == 0, 30)
    return process, port


class WebDriver:
    """The few W3C WebDriver commands these tests need."""

    def __init__(self, port, browser):
        self.base = "http://127.0.0.1:%d" % port
        capabilities = {"browserName": "chrome", "goog:chromeOptions": {
            "binary": browser, "args": ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=900,600",
                                        "--disable-dev-shm-usage"]}}
        self.session = self.call("POST", "/session", {"capabilities": {"alwaysMatch": capabilities}})["sessionId"]

    def call(self, method, path, body=None):
        data = json.dumps(body if body is not None else {}).encode() if method == "POST" else None
        request = urllib.request.Request(self.base + path, data=data, method=method,
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=120) as response:
                return json.loads(response.read())["value"]
        except urllib.error.HTTPError as e:
            fail("webdriver %s %s: %s" % (method, path, e.read()[:500]))

    def command(self, method, path, body=None):
        return self.call(method, "/session/%s%s" % (self.session, path), body)

    def script(self, source):
        return self.command("POST", "/execute/sync", {"script": source, "args": []})

    def element(self, css):
        found = self.command("POST", "/element", {"using": "css selector", "value": css})
        return next(iter(found.values()))

    def quit(self):
        try:
            request = urllib.request.Request(self.base + "/session/" + self.session, method="DELETE")
            urllib.request.urlopen(request, timeout=60).read()
        except OSError as e:
            print("webdriver: the session did not end: %s" % e)
