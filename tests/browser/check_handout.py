#!/usr/bin/env python3
"""Checks a handout folder (./fxlab handout) in a real browser: Debian's chromium, headless.

For every page (index.html, index.<lang>.html, and the same in each lesson folder):
  - links and pictures: every <img> file is there, every link leads to a page of the handout (and to
    an id on it), nothing is fetched from elsewhere, no script;
  - in chromium at the printed page's width (A4 less its margins) and at 1280 pixels: every picture
    loaded (a script added to a copy of the page looks), no element wider than the page;
  - a screenshot, and a PDF printed by chromium: A4, at least one page per step, each step starting a
    page of its own, no picture cut by a page break, no word outside the page's text area, and only
    the fonts the stylesheet names;
  - every character of the page's text is in one of the fonts the stylesheet names (fontconfig's
    charsets), so nothing shows as tofu.
Exits 0 when all is well, 1 on a failure (each one printed), 77 when chromium or poppler is missing.

  check_handout.py HANDOUT_DIR WORK_DIR
"""
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77
# The fonts style.css names (res/handout/style.css), by family and by the name a PDF embeds them under.
NAMED_FAMILIES = ["DejaVu Sans", "DejaVu Sans Mono", "IPAPGothic", "IPAGothic"]
NAMED_PDF_FONTS = re.compile(r"^(DejaVuSans|DejaVuSansMono|IPAPGothic|IPAGothic)(-[A-Za-z]+)?$")
A4_TEXT_WIDTH_PX = round((210 - 2 * 14) / 25.4 * 96)  # style.css: @page A4, 14 mm left and right
PDF_MARGIN_PT = 14 / 25.4 * 72
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--hide-scrollbars", "--allow-file-access-from-files"]

failures = []


def fail(page, message):
    failures.append(f"{page}: {message}")
    print(f"FAIL: {page}: {message}", flush=True)


class Page(html.parser.HTMLParser):
    """What a page holds: pictures, links, ids, scripts, steps, and its text by language."""

    def __init__(self):
        super().__init__()
        self.images, self.links, self.stylesheets, self.ids = [], [], [], set()
        self.scripts = 0
        self.steps = []  # (number, title text)
        self.text = []
        self._skip = 0
        self._in_step_heading = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "img":
            self.images.append(a.get("src", ""))
        elif tag == "a" and "href" in a:
            self.links.append(a["href"])
        elif tag == "link":
            self.stylesheets.append(a.get("href", ""))
        elif tag == "script":
            self.scripts += 1
        if tag in ("script", "style", "title"):
            self._skip += 1
        if tag == "section" and "step" in a.get("class", "").split():
            self.steps.append([a.get("id", ""), ""])
            self._in_step_heading = False
        if tag == "h2" and self._in_step_heading is False:
            self._in_step_heading = True
        for key in ("alt",):
            if a.get(key):
                self.text.append(a[key])

    def handle_endtag(self, tag):
        if tag in ("script", "style", "title") and self._skip:
            self._skip -= 1
        if tag == "h2" and self._in_step_heading:
            self._in_step_heading = None

    def handle_data(self, data):
        if not self._skip:
            self.text.append(data)
        if self._in_step_heading:
            self.steps[-1][1] += data


def parse(path):
    page = Page()
    with open(path, encoding="utf-8") as f:
        page.feed(f.read())
    return page


def font_charsets():
    """family -> set of code points, from fontconfig (the regular style of each named family)."""
    out = {}
    for family in NAMED_FAMILIES:
        listing = subprocess.run(["fc-list", "-f", "%{family}\t%{style}\t%{charset}\n", family],
                                 capture_output=True, text=True).stdout
        points = set()
        for line in listing.splitlines():
            families, style, charset = line.split("\t")
            if family not in families.split(",") or not re.search(r"Regular|Book", style):
                continue
            for r in charset.split():
                low, _, high = r.partition("-")
                points.update(range(int(low, 16), int(high or low, 16) + 1))
        out[family] = points
    return out


def chromium(binary, args, url, profile):
    return subprocess.run([binary] + CHROMIUM_FLAGS + [f"--user-data-dir={profile}"] + args + [url],
                          capture_output=True, text=True, timeout=180)


CHECK_SCRIPT = """<script>
window.addEventListener('load', function () {
  var r = {broken: [], overflow: [], scrollWidth: document.documentElement.scrollWidth,
           width: document.documentElement.clientWidth};
  for (var i = 0; i < document.images.length; ++i) {
    var img = document.images[i];
    if (!img.complete || img.naturalWidth === 0) r.broken.push(img.getAttribute('src'));
  }
  var all = document.body.querySelectorAll('*');
  for (var k = 0; k < all.length; ++k) {
    var el = all[k], b = el.getBoundingClientRect();
    var clipped = /^(PRE|TD|TH|P|LI|FIGCAPTION)$/.test(el.tagName) && el.scrollWidth > el.clientWidth + 1;
    if ((b.width > 0 && b.right > r.width + 1) || clipped)
      r.overflow.push(el.tagName + '.' + el.className + ' (' + Math.round(b.right) + ' > ' + r.width + '): ' +
                      (el.textContent || el.getAttribute('src') || '').trim().slice(0, 70));
  }
  var pre = document.createElement('pre');
  pre.id = 'fx-check';
  pre.textContent = JSON.stringify(r);
  document.body.appendChild(pre);
});
</script>
"""


def check_in_browser(binary, path, name, work, profile):
    """Loads a copy of the page with CHECK_SCRIPT at two widths; reports broken pictures and overflow."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    probe = os.path.join(os.path.dirname(path), ".fx-check-" + os.path.basename(path))
    with open(probe, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", CHECK_SCRIPT + "</body>"))
    try:
        for width in (A4_TEXT_WIDTH_PX, 1280):
            run = chromium(binary, [f"--window-size={width},1000", "--virtual-time-budget=20000", "--dump-dom"],
                           "file://" + probe, profile)
            found = re.search(r'<pre id="fx-check">(.*?)</pre>', run.stdout, re.S)
            if not found:
                fail(name, f"chromium at {width} px gave no result (exit {run.returncode}): {run.stderr[-400:]}")
                continue
            result = json.loads(html.unescape(found.group(1)))
            for src in result["broken"]:
                fail(name, f"the picture {src} did not load in chromium")
            if result["scrollWidth"] > result["width"] + 1:
                fail(name, f"at {width} px the page is {result['scrollWidth']} px wide")
            for what in result["overflow"][:10]:
                fail(name, f"at {width} px wider than the page: {what}")
    finally:
        os.remove(probe)


def check_pdf(binary, path, name, page, work, profile):
    pdf = os.path.join(work, name.replace("/", "_") + ".pdf")
    run = chromium(binary, [f"--print-to-pdf={pdf}", "--no-pdf-header-footer", "--virtual-time-budget=20000"],
                   "file://" + path, profile)
    if not os.path.isfile(pdf):
        fail(name, f"chromium printed no PDF (exit {run.returncode}): {run.stderr[-400:]}")
        return
    info = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout
    pages = int(re.search(r"^Pages:\s+(\d+)", info, re.M).group(1))
    if "(A4)" not in info:
        fail(name, "the PDF's pages are not A4")
    if pages < len(page.steps):
        fail(name, f"the PDF has {pages} pages for {len(page.steps)} steps")
    # Each step starts a page: its heading is the first line of some page.
    text = subprocess.run(["pdftotext", "-enc", "UTF-8", pdf, "-"], capture_output=True, text=True).stdout
    firsts = []
    for p in text.split("\f"):
        lines = [l.strip() for l in p.splitlines() if l.strip()]
        firsts.append(" ".join(lines[:2]) if lines else "")
    for step_id, heading in page.steps:
        words = " ".join(heading.split())
        if not any(" ".join(f.split()).startswith(words[:40]) for f in firsts):
            fail(name, f"{step_id} ({words[:50]}) does not start a page of the PDF")
    # No word outside the text area of its page.
    bbox = subprocess.run(["pdftotext", "-bbox", pdf, "-"], capture_output=True, text=True).stdout
    for pw, body in re.findall(r'<page width="([\d.]+)" height="[\d.]+">(.*?)</page>', bbox, re.S):
        right = float(pw) - PDF_MARGIN_PT + 1
        for x0, x1, word in re.findall(r'<word xMin="([\d.]+)" yMin="[\d.]+" xMax="([\d.]+)" yMax="[\d.]+">(.*?)</word>', body):
            if float(x1) > right or float(x0) < PDF_MARGIN_PT - 1:
                fail(name, f"the word \"{html.unescape(word)}\" runs past the page's margin ({float(x1):.0f} pt)")
                break
    # No picture cut by a page break: a cut one is drawn on two pages one after the other, at the same
    # size (the same picture shown twice, at another size, is not cut).
    pages_of = {}
    for line in subprocess.run(["pdfimages", "-list", pdf], capture_output=True, text=True).stdout.splitlines()[2:]:
        fields = line.split()
        pages_of.setdefault((fields[10], fields[12], fields[13]), []).append(int(fields[0]))
    for pages_drawn in pages_of.values():
        if any(b == a + 1 for a, b in zip(pages_drawn, pages_drawn[1:])):
            fail(name, f"a picture is cut by a page break (pages {pages_drawn[0]} and {pages_drawn[1]})")
    # Only the fonts the stylesheet names were used (a glyph they lack would bring another font in).
    fonts = subprocess.run(["pdffonts", pdf], capture_output=True, text=True).stdout.splitlines()[2:]
    for line in fonts:
        font = line.split()[0]
        if font == "[none]":
            continue  # Type 3: chromium's own drawing of a synthesised bold, not a font of the system
        font = font.split("+", 1)[-1]
        if not NAMED_PDF_FONTS.match(font):
            fail(name, f"the PDF uses the font {font}, which style.css does not name")
    return pdf


def check_text_glyphs(page, name, charsets):
    covered = set().union(*charsets.values())
    missing = sorted({c for c in "".join(page.text) if ord(c) > 0x20 and ord(c) not in covered})
    if missing:
        fail(name, "characters no named font has (tofu): " + " ".join(f"{c} U+{ord(c):04X}" for c in missing[:20]))


def check_links(path, name, page):
    folder = os.path.dirname(path)
    if page.scripts:
        fail(name, f"{page.scripts} script(s): a handout needs none")
    for src in page.images + page.stylesheets:
        if re.match(r"^[a-z]+:|^//", src):
            fail(name, f"{src} would be fetched from elsewhere")
        elif not os.path.isfile(os.path.join(folder, src)) or os.path.getsize(os.path.join(folder, src)) == 0:
            fail(name, f"missing file: {src}")
    for href in page.links:
        if re.match(r"^[a-z]+:|^//", href):
            fail(name, f"a link leaves the handout: {href}")
            continue
        target, _, fragment = href.partition("#")
        target_path = os.path.normpath(os.path.join(folder, target)) if target else path
        if not os.path.isfile(target_path):
            fail(name, f"broken link: {href}")
        elif fragment and fragment not in parse(target_path).ids:
            fail(name, f"broken link: {href} (no id \"{fragment}\" there)")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    handout, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    binary = shutil.which("chromium") or shutil.which("chromium-browser")
    missing = [tool for tool in ("pdfinfo", "pdftotext", "pdffonts", "pdfimages", "fc-list") if not shutil.which(tool)]
    if not binary or missing:
        print(f"SKIP: {'chromium' if not binary else ', '.join(missing)} not installed "
              "(Debian: chromium poppler-utils; ./fxlab test installs them as root)")
        return SKIP
    os.makedirs(work, exist_ok=True)
    charsets = font_charsets()
    for family, points in charsets.items():
        if not points:
            fail("fonts", f"{family}, named by style.css, is not installed")
    pages = []
    for root, dirs, files in os.walk(handout):
        dirs.sort()
        pages += [os.path.join(root, f) for f in sorted(files) if re.match(r"^index(\.[a-z]+)?\.html$", f)]
    if not pages:
        fail(handout, "no page")
    profile = tempfile.mkdtemp(prefix="fx-chromium-")
    try:
        for path in pages:
            name = os.path.relpath(path, handout)
            page = parse(path)
            check_links(path, name, page)
            check_text_glyphs(page, name, charsets)
            check_in_browser(binary, path, name, work, profile)
            shot = os.path.join(work, name.replace("/", "_") + ".png")
            chromium(binary, [f"--screenshot={shot}", "--window-size=1280,1600", "--virtual-time-budget=20000"],
                     "file://" + path, profile)
            if not os.path.isfile(shot) or os.path.getsize(shot) < 1000:
                fail(name, "chromium took no screenshot")
            check_pdf(binary, path, name, page, work, profile)
            print(f"checked {name}: {len(page.steps)} steps, {len(page.images)} pictures, {len(page.links)} links",
                  flush=True)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    if failures:
        print(f"{len(failures)} failure(s)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
