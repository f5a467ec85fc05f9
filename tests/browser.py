"""A headless Chromium driven through chromedriver's W3C WebDriver HTTP API, with the standard library
only (no selenium): open a page, run a script in it, read the browser's console log, take a
screenshot, print to PDF.

Debian: ``apt-get install chromium chromium-driver`` (.ci/run does it where it can).
:func:`find_browser` says why there is none, for a test to skip with that reason.
"""

from __future__ import annotations

import base64
import json
import shutil
import socket
import subprocess
import tempfile
import time
import urllib.error
import urllib.request
from pathlib import Path
from typing import Any

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
#: Chromium flags for a quiet, offline, reproducible headless run (no sandbox: CI runs as root in containers)
FLAGS = ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-default-apps", "--disable-extensions", "--no-first-run", "--hide-scrollbars",
         "--force-device-scale-factor=1")


def find_browser() -> tuple[str | None, str | None, str]:
    """(browser binary, chromedriver binary, reason when one is missing: "" when both are found)."""
    browser = next((p for p in map(shutil.which, BROWSERS) if p), None)
    driver = shutil.which("chromedriver")
    if browser is None:
        return None, driver, ("no Chromium or Chrome binary on PATH (looked for " + ", ".join(BROWSERS)
                              + "; Debian: apt-get install chromium chromium-driver)")
    if driver is None:
        return browser, None, f"{browser} found but no chromedriver on PATH (Debian: apt-get install chromium-driver)"
    return browser, driver, ""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Browser:
    """One chromedriver process and one browser session; a context manager that stops both."""

    def __init__(self, browser: str, driver: str, width: int = 1280, height: int = 1600, timeout_s: float = 30.0):
        self.timeout_s = timeout_s
        self.port = _free_port()
        self._profile = tempfile.TemporaryDirectory(prefix="spindlesim-chromium-")
        self._driver = subprocess.Popen([driver, f"--port={self.port}"], stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL)
        try:
            self._wait_ready()
            args = [*FLAGS, f"--user-data-dir={self._profile.name}", f"--window-size={width},{height}"]
            caps = {"capabilities": {"alwaysMatch": {
                "browserName": "chrome", "goog:chromeOptions": {"binary": browser, "args": args},
                "goog:loggingPrefs": {"browser": "ALL"}}}}
            self.session = self._call("POST", "/session", caps)["sessionId"]
        except BaseException:
            self._stop_driver()
            raise

    def __enter__(self) -> "Browser":
        return self

    def __exit__(self, *exc: Any) -> None:
        try:
            self._call("DELETE", f"/session/{self.session}")
        except (OSError, RuntimeError):
            pass
        finally:
            self._stop_driver()

    def _stop_driver(self) -> None:
        self._driver.terminate()
        try:
            self._driver.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self._driver.kill()
            self._driver.wait()
        self._profile.cleanup()

    def _wait_ready(self) -> None:
        deadline = time.monotonic() + self.timeout_s
        while time.monotonic() < deadline:
            if self._driver.poll() is not None:
                raise RuntimeError(f"chromedriver exited with code {self._driver.returncode}")
            try:
                if self._call("GET", "/status", timeout_s=2.0).get("ready"):
                    return
            except OSError:
                pass
            time.sleep(0.05)
        raise RuntimeError(f"chromedriver not ready after {self.timeout_s:g} s")

    def _call(self, method: str, path: str, body: dict | None = None, timeout_s: float | None = None) -> Any:
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(f"http://127.0.0.1:{self.port}{path}", data=data, method=method,
                                     headers={"Content-Type": "application/json; charset=utf-8"})
        try:
            with urllib.request.urlopen(req, timeout=timeout_s or self.timeout_s) as resp:
                return json.loads(resp.read())["value"]
        except urllib.error.HTTPError as exc:  # a WebDriver error: {"value": {"error", "message"}}
            detail = json.loads(exc.read() or b"{}").get("value", {})
            raise RuntimeError(f"{method} {path}: {detail.get('error')}: {detail.get('message')}") from None

    def _session(self, method: str, path: str, body: dict | None = None) -> Any:
        return self._call(method, f"/session/{self.session}{path}", body)

    # --- what a test uses ---
    def open(self, path: Path) -> None:
        """Load a local file; returns once the page's load event has fired."""
        self._session("POST", "/url", {"url": Path(path).resolve().as_uri()})

    def script(self, source: str, *args: Any) -> Any:
        """Run ``source`` (a function body; ``return`` gives the result) in the page."""
        return self._session("POST", "/execute/sync", {"script": source, "args": list(args)})

    def console(self) -> list[dict]:
        """The browser's console and network log entries since the last call (level, source, message)."""
        return self._session("POST", "/se/log", {"type": "browser"})

    def screenshot(self) -> bytes:
        """PNG of the viewport (the first screen)."""
        return base64.b64decode(self._session("GET", "/screenshot"))

    def pdf(self, width_cm: float = 21.0, height_cm: float = 29.7) -> bytes:
        """The page printed to PDF on paper of that size (default A4), backgrounds included."""
        return base64.b64decode(self._session("POST", "/print", {
            "page": {"width": width_cm, "height": height_cm}, "background": True}))
