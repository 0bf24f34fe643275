#!/usr/bin/env python3
"""Browser test of `dualhex atlas`: headless Chromium (Debian's chromium) loads pages of a
freshly written atlas and the test fails if a page logs anything to the console (an error
in particular), if a canvas shows only the background colour, or if a count shown in a
table differs from the one the dualhex CLI prints with --json. All pages are checked for
counts through the site's atlas.json and their embedded data; a representative subset
(the index, one page of each kind, plus one MR element) is loaded in the browser.

Usage: atlas_browser_test.py DUALHEX_EXE [CHROMIUM]. Exit 77 (CTest skip) if Chromium is absent.
"""
import html.parser
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

BACKGROUND = (0xF7, 0xF7, 0xF2)  # atlas.js's clear colour
# The only console message a page may produce: swiftshader's performance notice when the
# screenshot reads the canvas back (the GL driver's, not the page's).
DRIVER_NOTICE = re.compile(r'"\[\.WebGL-[0-9a-fx]+\]GL Driver Message \(OpenGL, Performance')
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--enable-logging=stderr", "--v=0",
                  "--window-size=1300,900"]

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, flush=True)


def run_json(exe, *args):
    out = subprocess.run([exe, *args, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


# ---- PNG decoding (8-bit RGB/RGBA, non-interlaced: what Chromium writes) ----
def decode_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path + ": not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, path + ": unsupported PNG format"
    channels = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1: line[i] = (line[i] + a) & 255
            elif kind == 2: line[i] = (line[i] + b) & 255
            elif kind == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows


def foreground_fraction(png, rect):
    """Fraction of the canvas's pixels (rect = x, y, w, h, inset by 2 px for the border) that
    differ from the background colour."""
    width, height, channels, rows = decode_png(png)
    x, y, w, h = rect
    count = differ = 0
    for py in range(max(0, y + 2), min(height, y + h - 2)):
        row = rows[py]
        for px in range(max(0, x + 2), min(width, x + w - 2)):
            count += 1
            differ += tuple(row[px * channels:px * channels + 3]) != BACKGROUND
    return differ / count if count else 0.0


# ---- the DOM as Chromium dumps it ----
class TableReader(html.parser.HTMLParser):
    """The page's tables: {table id: {row key: [cell texts]}} and body attributes."""
    def __init__(self):
        super().__init__()
        self.tables, self.body, self._table, self._row, self._cell = {}, {}, None, None, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body": self.body = a
        elif tag == "table": self._table = self.tables.setdefault(a.get("data-table"), {})
        elif tag == "tr" and self._table is not None and "data-key" in a:
            self._row = self._table.setdefault(a["data-key"], [])
        elif tag == "td" and self._row is not None: self._cell = ""

    def handle_endtag(self, tag):
        if tag == "td" and self._cell is not None: self._row.append(self._cell); self._cell = None
        elif tag == "tr": self._row = None
        elif tag == "table": self._table = None

    def handle_data(self, data):
        if self._cell is not None: self._cell += data


def load_in_browser(chromium, page, work, fragment=""):
    """(console messages, dumped DOM, screenshot path) of one page."""
    shot = os.path.join(work, os.path.basename(page) + ".png")
    profile = tempfile.mkdtemp(prefix="profile-", dir=work)
    proc = subprocess.run([chromium, *CHROMIUM_FLAGS, "--user-data-dir=" + profile, "--screenshot=" + shot,
                           "--dump-dom", "file://" + os.path.abspath(page) + ("#" + fragment if fragment else "")],
                          capture_output=True, text=True, timeout=120)
    console = [l for l in proc.stderr.splitlines() if ":CONSOLE" in l and not DRIVER_NOTICE.search(l)]
    return console, proc.stdout, shot


# ---- what the CLI says ----
def expected_tables(exe):
    """{page id: {table id: {key: value}}}: the counts the CLI prints with --json."""
    expected = {}
    for name in [e["name"] for e in run_json(exe, "element", "--list")["elements"] if "name" in e]:
        e = run_json(exe, "element", name)
        expected["element-" + name] = {"counts": dict(e["counts"]), "face_sizes": e["face_histogram"]}
    variants = run_json(exe, "variants")
    for region in ("flat", "concave_edge", "concave_corner"):
        for v in variants[region]["variants"]:
            expected["variant-" + v["name"]] = {"face_sizes": v["element_faces"], "bend_faces": v["bend_faces"],
                                                "dual_valences": v["dual_edge_valences"]}
    for c in run_json(exe, "table")["classes"]:
        expected["transition-%d" % c["representative"]] = {
            "leaves_at_p": {l["position"]: l["element"] for l in c["leaves"]}}
    return expected


def compare(page_id, shown, expected_page):
    """shown: {table id: {key: first value cell}} as strings or numbers."""
    for table, rows in expected_page.items():
        got = {k: v for k, v in shown.get(table, {}).items() if not (table == "face_sizes" and str(v) == "0")}
        want = {str(k): str(v) for k, v in rows.items()}
        got = {str(k): str(v) for k, v in got.items()}
        if got != want:
            fail("%s: table %s shows %s, the CLI says %s" % (page_id, table, got, want))


def main():
    if len(sys.argv) < 2:
        print("usage: atlas_browser_test.py DUALHEX_EXE [CHROMIUM]", file=sys.stderr)
        return 2
    exe = sys.argv[1]
    chromium = sys.argv[2] if len(sys.argv) > 2 else shutil.which("chromium") or "/usr/bin/chromium"
    if not os.access(chromium, os.X_OK):
        print("SKIP: chromium not found at %s (Debian package chromium)" % chromium)
        return 77
    work = tempfile.mkdtemp(prefix="atlas-browser-")
    site = os.path.join(work, "site")
    summary = run_json(exe, "atlas", "-o", site)
    expected = expected_tables(exe)
    kinds = {}
    for p in summary["pages"]:
        kinds.setdefault(p["kind"], []).append(p["id"])
    wanted = {"element": 13, "transition": 20, "weak": 14, "variant": 14}
    for kind, n in wanted.items():
        if len(kinds.get(kind, [])) != n: fail("%d %s pages, expected %d" % (len(kinds.get(kind, [])), kind, n))

    # Every page: its tables in atlas.json against the CLI.
    for p in summary["pages"]:
        shown = {t["id"]: {str(r[0]): r[1] for r in t["rows"]} for t in p["tables"]}
        if p["id"] in expected: compare(p["id"], shown, expected[p["id"]])
        elif p["kind"] in ("element", "variant", "transition"): fail(p["id"] + ": no CLI counterpart")
        if p["cells"] == 0 or p["dual_hexes"] == 0: fail(p["id"] + ": empty scene or dual")

    # A subset in the browser: one page of each kind and a few more, and the index.
    # (page, URL fragment presetting the controls: every colour mode, the dual and the clip plane drawn)
    subset = [("element-VC", ""), ("element-E-MR", "mode=size&dual=1"), (kinds["transition"][0], "dual=1&clip=1&clipAxis=z"),
              (kinds["weak"][0], "mode=element"), ("variant-edge-LU", "mode=size&explode=0.6")]
    shots = os.environ.get("DUALHEX_ATLAS_SCREENSHOTS")  # keep the screenshots there (README's)
    for page_id, fragment in subset:
        console, dom, shot = load_in_browser(chromium, os.path.join(site, page_id + ".html"), work, fragment)
        if shots: shutil.copy(shot, os.path.join(shots, "atlas-" + page_id + ".png"))
        for line in console: fail(page_id + ": console: " + line)
        reader = TableReader()
        reader.feed(dom)
        if "data-canvas" not in reader.body:
            fail(page_id + ": no canvas was laid out (the page script did not finish)")
            continue
        fraction = foreground_fraction(shot, [int(v) for v in reader.body["data-canvas"].split(",")])
        if fraction < 0.01: fail("%s: the canvas is blank (%.4f of its pixels differ from the background)" % (page_id, fraction))
        shown = {t: {k: cells[1] for k, cells in rows.items() if len(cells) > 1} for t, rows in reader.tables.items()}
        if page_id in expected: compare(page_id, shown, expected[page_id])
        print("ok %s: %.2f of the canvas drawn, %d tables" % (page_id, fraction, len(reader.tables)), flush=True)
    console, dom, _ = load_in_browser(chromium, os.path.join(site, "index.html"), work)
    for line in console: fail("index: console: " + line)
    for kind, n in wanted.items():
        if 'data-count="%s">%d<' % (kind, n) not in dom: fail("index: does not show %d %s pages" % (n, kind))

    # The harness itself: a page that throws must be caught.
    broken = os.path.join(site, "broken.html")
    with open(os.path.join(site, "element-F.html")) as f:
        text = f.read().replace("</body>", "<script>throw new Error('deliberate');</script></body>")
    with open(broken, "w") as f:
        f.write(text)
    if not any("deliberate" in l for l in load_in_browser(chromium, broken, work)[0]):
        fail("the console check did not see a deliberate error")
    # ... and a canvas left at the background colour must count as blank.
    blank = os.path.join(site, "blank.html")
    with open(blank, "w") as f:
        f.write('<html><body style="margin:0"><canvas id="c" width="720" height="540"></canvas><script>'
                'const c = document.getElementById("c"), g = c.getContext("2d"); g.fillStyle = "#f7f7f2";'
                'g.fillRect(0, 0, 720, 540); document.body.setAttribute("data-canvas", "0,0,720,540");'
                '</script></body></html>')
    _, dom, shot = load_in_browser(chromium, blank, work)
    if foreground_fraction(shot, (0, 0, 720, 540)) >= 0.01: fail("the pixel check did not see a blank canvas")

    if failures:
        print("%d failure(s); output kept in %s" % (len(failures), work))
        return 1
    shutil.rmtree(work)
    print("atlas browser test passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
