#!/usr/bin/env python3
"""The labs' web pages in headless Chromium (the `web` ctest label, tests/web/CMakeLists.txt).

check_pages.py SITE OUT [LAB...]: serves SITE (build/web) on a free loopback port, and for each lab of
cmake/web/labs.tsv (or those named, or those of $PBA_WEB_LABS) opens its default scene and its second scene, the latter with a
parameter set through the URL query. Chromium is driven through the DevTools protocol on a pipe
(--remote-debugging-pipe), so nothing but the standard library is needed. For each page it waits until
the lab has drawn REPORT frames, then checks that
  - the console shows no error and the page threw no exception;
  - the lab's status (window.pbaStatus(), cmake/web/query.js) names the scene of the query, and the
    parameter set in the query has that value;
  - the screenshot (OUT/LAB-SCENE.png) is not blank: many distinct colours;
  - on the default scene's page, "Open a file" copies a picked file into the page's file system.
Prints one line a page; exits 1 naming what failed."""
import base64
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import zlib

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--no-first-run", "--window-size=1280,720", "--hide-scrollbars", "--remote-debugging-pipe"]
REPORT_FRAMES = 60
FRAME = (1280, 720)  # the lab's frame (?size=), that of the desktop screenshots (--screenshot)
NOTE_ROOM = 40  # [px] the page's line under the canvas (cmake/web/shell.html) fits in this
PAGE_TIMEOUT_S = 240  # a page that never reaches its frames (a hang) fails instead of blocking ctest


class Chromium:
    """One headless Chromium, spoken to in DevTools protocol messages, NUL-terminated, on fds 3 and 4."""

    def __init__(self, exe, profile):
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()

        def child_fds():  # Chromium reads fd 3 and writes fd 4 (kept open by pass_fds below)
            read_end, write_end = os.dup(to_chrome_r), os.dup(from_chrome_w)  # out of the way of 3 and 4
            os.dup2(read_end, 3)
            os.dup2(write_end, 4)

        self.proc = subprocess.Popen([exe, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "about:blank"],
                                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL, preexec_fn=child_fds, pass_fds=(3, 4))
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            if time.monotonic() > deadline:
                raise TimeoutError("Chromium did not answer")
            chunk = os.read(self.from_chrome, 1 << 16)
            if not chunk:
                raise RuntimeError("Chromium closed its pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, session=None, timeout=60, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = session
        os.write(self.to_chrome, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def close(self):
        try:
            self.call("Browser.close", timeout=10)
        except Exception:  # noqa: BLE001 - closing anyway
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        os.close(self.to_chrome)
        os.close(self.from_chrome)


def console_errors(events, session):
    errors = []
    for e in events:
        if e.get("sessionId") != session:
            continue
        p = e.get("params", {})
        if e.get("method") == "Runtime.consoleAPICalled" and p.get("type") == "error":
            errors.append(" ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
        elif e.get("method") == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            errors.append(d.get("exception", {}).get("description") or d.get("text", "exception"))
        elif e.get("method") == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            errors.append(p["entry"].get("text", ""))
    return errors


def png_colours(data, step=7):
    """The number of distinct RGB colours among every step-th pixel of an 8-bit RGB/RGBA PNG."""
    pos, idat = 8, b""
    while pos < len(data):
        n = int.from_bytes(data[pos:pos + 4], "big")
        kind, chunk = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            width, height, depth, colour = chunk[0:4], chunk[4:8], chunk[8], chunk[9]
            width, height = int.from_bytes(width, "big"), int.from_bytes(height, "big")
        elif kind == b"IDAT":
            idat += chunk
    assert depth == 8 and colour in (2, 6), "an 8-bit RGB or RGBA PNG"
    bpp = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * bpp
    prev, seen, k = bytearray(stride), set(), 0
    for y in range(height):
        kind, line = raw[k], bytearray(raw[k + 1:k + 1 + stride])
        k += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        if y % step == 0:
            for x in range(0, width, step):
                seen.add(bytes(line[x * bpp:x * bpp + 3]))
        prev = line
    return len(seen)


def check_file_picker(chrome, session):
    """"Open a file" under the canvas copies the picked file into the page's file system (/picked/NAME,
    cmake/web/query.js): pick a model of the repository and compare the copy's size with the file's."""
    model = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                         "resources", "models", "humanoid.bvh")
    root = chrome.call("DOM.getDocument", session=session)["root"]["nodeId"]
    node = chrome.call("DOM.querySelector", session=session, nodeId=root, selector="#pick")["nodeId"]
    if not node:
        return ["no file picker (#pick) under the canvas"]
    chrome.call("DOM.setFileInputFiles", session=session, nodeId=node, files=[model])
    expression = "(function () { try { return FS.stat('/picked/humanoid.bvh').size; } catch (e) { return -1; } })()"
    size, deadline = -1, time.monotonic() + 30
    while size < 0 and time.monotonic() < deadline:
        size = chrome.call("Runtime.evaluate", session=session, returnByValue=True,
                           expression=expression).get("result", {}).get("value", -1)
        time.sleep(0.2)  # polling the page: the copy is asynchronous (File.arrayBuffer)
    if size != os.path.getsize(model):
        return [f"the picked file is not in the page's file system (/picked/humanoid.bvh: size {size})"]
    return []


def check_page(chrome, base, out, lab, scene, assignment):
    width, height = FRAME
    query = f"?scene={scene}&report={REPORT_FRAMES}&size={width}x{height}" + (f"&set={assignment}" if assignment else "")
    target = chrome.call("Target.createTarget", url="about:blank")["targetId"]
    session = chrome.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
    for domain in ("Runtime.enable", "Log.enable", "Page.enable", "DOM.enable"):
        chrome.call(domain, session=session)
    # Headless Chromium's viewport (1280x633 for a 1280x720 window) would cut the frame: the page gets
    # the frame's size and room for the line under the canvas.
    chrome.call("Emulation.setDeviceMetricsOverride", session=session, width=width, height=height + NOTE_ROOM,
                deviceScaleFactor=1, mobile=False)
    chrome.call("Page.navigate", session=session, url=f"{base}/pba-{lab}.html{query}")
    status, deadline = None, time.monotonic() + PAGE_TIMEOUT_S
    failures = []
    while time.monotonic() < deadline:
        value = chrome.call("Runtime.evaluate", session=session, returnByValue=True,
                            expression="window.pbaStatus ? JSON.stringify(window.pbaStatus()) : null")
        text = value.get("result", {}).get("value")
        status = json.loads(text) if text and text != "null" else None
        if status and status.get("frame", 0) >= REPORT_FRAMES:
            break
        if console_errors(chrome.events, session):
            break
        time.sleep(0.5)  # polling the page, not a timed assertion: the deadline only bounds a hang
    frame = {"x": 0, "y": 0, "width": width, "height": height, "scale": 1}  # the canvas: the lab's frame
    shot = base64.b64decode(chrome.call("Page.captureScreenshot", session=session, format="png", clip=frame)["data"])
    png = os.path.join(out, f"{lab}-{scene}.png")
    with open(png, "wb") as f:
        f.write(shot)
    failures += [f"console error: {e}" for e in console_errors(chrome.events, session)]
    if not status or status.get("frame", 0) < REPORT_FRAMES:
        failures.append(f"the lab did not draw {REPORT_FRAMES} frames in {PAGE_TIMEOUT_S} s")
    else:
        if status.get("scene") != scene:
            failures.append(f"scene is {status.get('scene')!r}, the query asked for {scene!r}")
        if assignment:
            name, value = assignment.split("=", 1)
            got = status.get("params", {}).get(name)
            if got is None or abs(float(got) - float(value)) > 1e-9 * max(1.0, abs(float(value))):
                failures.append(f"parameter {name} is {got!r}, the query set {value}")
    if not assignment:
        failures += check_file_picker(chrome, session)
    colours = png_colours(shot)
    if colours < 64:
        failures.append(f"the screenshot looks blank ({colours} colours)")
    chrome.call("Target.closeTarget", targetId=target)
    with open(os.path.join(out, f"{lab}-{scene}.json"), "w") as f:
        json.dump({"status": status, "failures": failures}, f, indent=1)
    return failures, status


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    site, out, wanted = sys.argv[1], sys.argv[2], sys.argv[3:] or os.environ.get("PBA_WEB_LABS", "").split()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    rows = []
    with open(os.path.join(root, "cmake", "web", "labs.tsv"), encoding="utf-8") as f:
        for line in f:
            cols = line.rstrip("\n").split("\t")
            if not line.startswith("#") and len(cols) >= 5 and (not wanted or cols[0] in wanted):
                rows.append(cols)
    exe = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if not exe:
        print("check_pages: no chromium on the PATH", file=sys.stderr)
        return 2
    os.makedirs(out, exist_ok=True)
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=site)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}"
    profile = tempfile.mkdtemp(prefix="pba-chromium-")
    chrome = Chromium(exe, profile)
    bad = 0
    try:
        for lab, default, second, assignment, _ in rows:
            for scene, setting in ((default, ""), (second, assignment)):
                failures, status = check_page(chrome, base, out, lab, scene, setting)
                physics = status.get("metrics", {}) if status else {}
                print(f"{'FAIL' if failures else 'ok  '} {lab}/{scene}{' ' + setting if setting else ''}"
                      f"{': ' + '; '.join(failures) if failures else ''}", flush=True)
                bad += bool(failures)
    finally:
        chrome.close()
        server.shutdown()
        shutil.rmtree(profile, ignore_errors=True)
    print(f"{sum(2 for _ in rows) - bad} of {2 * len(rows)} pages passed; screenshots in {out}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
