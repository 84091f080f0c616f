#!/usr/bin/python3
"""Opens a CityLangSplat report (report/index.html) from disk in headless Chromium and checks that a
person would see it whole: no console error, every <img> decoded, the expected tables and SVG charts
present, and a full-page screenshot that is not blank (written to --screenshot).

Run it with Debian's /usr/bin/python3 (python3-selenium, python3-pil; chromium and chromium-driver).
Exit status: 0 pass, 1 fail (with the reasons), 77 skipped (Chromium, chromedriver, Selenium or PIL absent).

    /usr/bin/python3 tests/report/browser_check.py RUN/report/index.html --screenshot shot.png
"""
import argparse
import base64
import io
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from headless_chromium import require_tools, start_browser  # noqa: E402

# What a complete report shows (tests/report/sample_run.h makes one): CSS selector -> minimum count.
COMPLETE_REPORT = {
    "img": 8,  # label previews, photo/render pairs, relevance maps, GT/prediction images
    "table#stages-table": 1,
    "table#settings": 1,
    "table#table-1": 1,
    "table#table-1b": 1,
    "table#table-2": 1,
    "table#table-2b": 1,
    "table#table-3": 1,
    "table#queries-table": 1,
    "table#eval-views": 1,
    "svg.chart": 5,
    "#warning": 1,
}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("page", help="the report's index.html")
    p.add_argument("--screenshot", required=True, help="where to write the full-page PNG screenshot")
    p.add_argument("--expect", action="append", metavar="SELECTOR=COUNT",
                   help="a CSS selector and its minimum count (repeatable; default: a complete report's tables, "
                        "charts and warning banner)")
    return p.parse_args()


def expectations(args):
    if not args.expect:
        return COMPLETE_REPORT
    out = {}
    for e in args.expect:
        selector, _, count = e.rpartition("=")
        if not selector or not count.isdigit():
            sys.exit(f"--expect {e!r}: expected SELECTOR=COUNT")
        out[selector] = int(count)
    return out


def full_page_png(driver):
    """A screenshot of the whole page, beyond the window (Chrome DevTools protocol)."""
    metrics = driver.execute_cdp_cmd("Page.getLayoutMetrics", {})
    size = metrics.get("cssContentSize") or metrics["contentSize"]
    shot = driver.execute_cdp_cmd("Page.captureScreenshot", {
        "format": "png", "captureBeyondViewport": True,
        "clip": {"x": 0, "y": 0, "width": size["width"], "height": size["height"], "scale": 1}})
    return base64.b64decode(shot["data"])


def blank_reason(png):
    """Why the screenshot looks blank, or None: too few colours, or (nearly) all white."""
    from PIL import Image
    img = Image.open(io.BytesIO(png)).convert("RGB")
    img.thumbnail((800, 800))
    colours = img.getcolors(maxcolors=1 << 20)
    if colours is not None and len(colours) < 64:
        return f"only {len(colours)} distinct colours"
    pixels = img.getdata()
    dark = sum(1 for r, g, b in pixels if min(r, g, b) < 200)
    if dark < 0.02 * len(pixels):
        return f"only {100.0 * dark / len(pixels):.2f}% of the pixels are not near-white"
    return None


def main():
    args = parse_args()
    page = os.path.abspath(args.page)
    if not os.path.isfile(page):
        print(f"FAIL: {page}: no such file")
        return 1
    require_tools()
    driver = start_browser()
    failures = []
    try:
        driver.get("file://" + page)  # returns after the load event: every image has loaded or failed
        broken = driver.execute_script(
            "return Array.from(document.images)"
            ".filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'));")
        images = driver.execute_script("return document.images.length;")
        for src in broken:
            failures.append(f"broken image: {src}")
        for selector, minimum in expectations(args).items():
            n = driver.execute_script("return document.querySelectorAll(arguments[0]).length;", selector)
            if n < minimum:
                failures.append(f"expected at least {minimum} of {selector!r}, found {n}")
        for entry in driver.get_log("browser"):
            if entry.get("level") == "SEVERE":
                failures.append(f"console error: {entry.get('message')}")
        png = full_page_png(driver)
    finally:
        driver.quit()
    os.makedirs(os.path.dirname(os.path.abspath(args.screenshot)), exist_ok=True)
    with open(args.screenshot, "wb") as f:
        f.write(png)
    reason = blank_reason(png)
    if reason:
        failures.append(f"the screenshot looks blank: {reason}")
    if failures:
        print(f"FAIL: {page}")
        for f in failures:
            print(f"  {f}")
        print(f"screenshot: {args.screenshot}")
        return 1
    print(f"PASS: {page}: {images} images decoded, no console error, screenshot {args.screenshot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
