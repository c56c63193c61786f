"""A chapter executable run with --live, for the live view's tests (live_http.py, live_browser.py), or the
sampler view (sampler_view_browser.py), which serves without it."""
import atexit
import http.client
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from urllib.parse import quote


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class LiveRun:
    """Starts `executable --live --port 0 ARGS` (`serve` instead of --live) in an empty folder and reads the port
    it prints."""

    def __init__(self, executable, *args, serve=("--live",)):
        self.folder = tempfile.mkdtemp(prefix="rt-live-")
        self.stderr = tempfile.TemporaryFile("w+")
        self.process = subprocess.Popen([os.path.abspath(executable), *serve, "--port", "0", *args], cwd=self.folder,
                                        stdout=subprocess.PIPE, stderr=self.stderr, text=True)
        atexit.register(self.end)  # a test that fails leaves no server behind
        line = self.process.stdout.readline()
        found = re.search(r"(?:live|sampler) view on http://127\.0\.0\.1:(\d+)/", line)
        if not found:
            self.process.kill()
            fail("no live view line on stdout, got %r; stderr: %s" % (line, self.errors()))
        self.port = int(found.group(1))
        self.host = "127.0.0.1:%d" % self.port

    def errors(self):
        self.stderr.flush()
        self.stderr.seek(0)
        return self.stderr.read()[-2000:]

    def request(self, method, path, headers=None):
        """(status, body bytes) of one request; the Host is 127.0.0.1:PORT unless `headers` says otherwise."""
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=120)
        connection.putrequest(method, path, skip_host=True)
        for name, value in {"Host": self.host, **(headers or {})}.items():
            connection.putheader(name, value)
        if method == "POST":
            connection.putheader("Content-Length", "0")
        connection.endheaders()
        response = connection.getresponse()
        body = response.read()
        connection.close()
        return response.status, body

    def state(self):
        status, body = self.request("GET", "/state")
        if status != 200:
            fail("/state: status %d" % status)
        return json.loads(body)

    def change(self, kind, name, value):
        query = "kind=%s&name=%s&value=%s" % tuple(quote(t, safe="") for t in (kind, name, value))
        status, body = self.request("POST", "/change?" + query)
        return status, body.decode().strip()

    def wait_for(self, what, predicate, seconds=60):
        """The first state for which predicate(state) holds, within `seconds`."""
        deadline = time.time() + seconds
        while time.time() < deadline:
            state = self.state()
            if predicate(state):
                return state
            time.sleep(0.05)
        fail("waited %g s for %s; last state: %s" % (seconds, what, json.dumps(state)[:600]))

    def interrupt(self, seconds=30):
        """SIGINT; the exit status, within `seconds`."""
        self.process.send_signal(signal.SIGINT)
        try:
            return self.process.wait(seconds)
        except subprocess.TimeoutExpired:
            self.process.kill()
            fail("SIGINT: the run did not end within %g s" % seconds)

    def files_written(self):
        return sorted(os.listdir(self.folder))

    def end(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
