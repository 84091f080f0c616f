#!/usr/bin/python3
"""Checks the viewer of `citylangsplat view` in a real browser: starts the server, opens the page in
headless Chromium (software WebGL), checks the view it opens at, jumps to a view, types a query as a
person would, and checks that the splats that changed colour lie on the queried class in that view's
label map.

The first view (before any input): the page must open through the first training camera (the views
sorted by name, every --test-every-th from the first held out, as train-rgb splits them): the camera's
position, orientation and projection must be that view's centre, R and intrinsics from /api/model, and
the canvas its aspect ratio. The building must show in it: at least --min-first-centre of the central
half (each axis) of the canvas differs from the page's empty background, and on the pixels where the
view's label map has a city object (level 3 label > 0) the render matches the view's photo to a mean
absolute difference of at most --max-first-error (0-255): the centre share catches a blank canvas, the
photo a view of the wrong place (the old far, fogged overview covered 99% of the centre but differed by
33). "hide far splats" must be on and hide some splats (the sample's sky), at most --max-hidden of
them. The screenshot goes to --first-screenshot.

Highlighted pixels are those whose colour changed between the render before and after the query by
more than --min-change (max over R, G, B, 0-255): the page mixes 80% of a heat colour over a selected
splat, while a fixed camera re-renders the other splats identically. The canvas shows exactly the
view (its aspect ratio, letterboxed), so its screenshot is resized (nearest) onto the label map
LABELS/<view stem>/level<L>.png, where the class's pixels hold its legend.json id + 1.
Pass: at least --min-fraction of the highlighted pixels are on the class, and at least --min-pixels
(a fraction of the label map) are highlighted, so that an empty highlight fails; no SEVERE console entry.

Run it with Debian's /usr/bin/python3 (python3-selenium, python3-pil; chromium and chromium-driver).
Exit status: 0 pass, 1 fail (with the reasons), 77 skipped (Chromium, chromedriver, Selenium or PIL absent).

    /usr/bin/python3 tests/viewer/browser_query_check.py --binary build/citylangsplat --out RUN \\
        --labels RUN/labels --view 0000.png --query window --class window --level 1 --screenshot after.png
"""
import argparse
import io
import json
import os
import queue
import re
import subprocess
import sys
import threading
import time
import urllib.request

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from headless_chromium import require_tools, start_browser  # noqa: E402

SERVER_URL = re.compile(r"http://127\.0\.0\.1:\d+/")
BACKGROUND = (0x20, 0x22, 0x26)  # the page's scene.background, where no splat covers the canvas


class Failure(Exception):
    pass


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", help="the citylangsplat executable (runs `BINARY view OUT --port 0`)")
    p.add_argument("--out", help="the run or model directory to view")
    p.add_argument("--labels", required=True, help="label maps: LABELS/legend.json, LABELS/<view stem>/level<L>.png")
    p.add_argument("--view", required=True, help="the view to look through, as the page lists it (e.g. 0000.png)")
    p.add_argument("--query", required=True, help="the text typed into the query box")
    p.add_argument("--class", dest="cls", required=True, help="the legend class the highlight must fall on")
    p.add_argument("--level", type=int, choices=(1, 2, 3), required=True, help="query level and label map level")
    p.add_argument("--mode", choices=("cosine", "relevancy"), default="cosine")
    p.add_argument("--threshold", type=float, help="set the threshold slider to this (default: the page's)")
    p.add_argument("--min-fraction", type=float, default=0.8, help="least share of highlighted pixels on the class")
    p.add_argument("--min-pixels", type=float, default=0.005,
                   help="least highlighted pixels, as a fraction of the label map (default 0.5%%)")
    p.add_argument("--min-change", type=int, default=40, help="colour change (0-255) that makes a pixel highlighted")
    p.add_argument("--timeout", type=float, default=180, help="seconds to wait for loading, and for the query")
    p.add_argument("--screenshot", help="write the full page after the query here (PNG)")
    p.add_argument("--first-screenshot",
                   help="write the full page as it opens here (PNG; default: --screenshot's name + _first.png)")
    p.add_argument("--test-every", type=int, default=8, help="train-rgb's split: views k %% N == 0 by name are held out")
    p.add_argument("--min-first-centre", type=float, default=0.6,
                   help="least share of the first view's central pixels not showing the empty background")
    p.add_argument("--max-first-error", type=float, default=15,
                   help="largest mean absolute difference (0-255) between the first view's render and its photo "
                        "on the city model's pixels")
    p.add_argument("--max-hidden", type=float, default=0.1,
                   help="largest share of the splats that 'hide far splats' may hide (and it must hide some)")
    p.add_argument("--keep-server", action="store_true", help="leave the server running at the end")
    p.add_argument("--server-url", help=argparse.SUPPRESS)  # use a running server (development against a mock)
    args = p.parse_args()
    if not args.server_url and not (args.binary and args.out):
        p.error("--binary and --out are required")
    if args.first_screenshot is None and args.screenshot:
        args.first_screenshot = os.path.splitext(args.screenshot)[0] + "_first.png"
    return args


def load_labels(args):
    """The label map of the view at the level (PIL image, mode I) and the class's label value."""
    from PIL import Image
    legend_path = os.path.join(args.labels, "legend.json")
    with open(legend_path) as f:
        legend = json.load(f)
    ids = [c["id"] for c in legend if c.get("name") == args.cls]
    if not ids:
        raise Failure(f"{legend_path}: no class '{args.cls}' (classes: {', '.join(c.get('name', '?') for c in legend)})")
    stem = os.path.splitext(args.view)[0]
    path = os.path.join(args.labels, stem, f"level{args.level}.png")
    if not os.path.isfile(path):
        raise Failure(f"{path}: no such label map")
    return Image.open(path).convert("I"), ids[0] + 1


def start_server(args):
    """Runs `BINARY view OUT --port 0` and returns (process, url) once it says where it listens."""
    cmd = [args.binary, "view", args.out, "--port", "0"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    lines = queue.Queue()

    def pump():  # a thread, so that waiting for the URL can time out
        for line in proc.stdout:
            lines.put(line)
        lines.put(None)

    threading.Thread(target=pump, daemon=True).start()
    seen = []
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        try:
            line = lines.get(timeout=max(0.1, deadline - time.monotonic()))
        except queue.Empty:
            break
        if line is None:
            proc.wait()
            raise Failure(f"{' '.join(cmd)} exited with {proc.returncode} before listening:\n{''.join(seen)}")
        seen.append(line)
        match = SERVER_URL.search(line)
        if match:
            return proc, match.group(0)
    stop_server(proc)
    raise Failure(f"{' '.join(cmd)} printed no http://127.0.0.1:PORT/ within 60 s:\n{''.join(seen)}")


def stop_server(proc):
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def wait_for(driver, what, script, timeout):
    """Polls a JS expression on window.viewerState until it is truthy; returns its value."""
    deadline = time.monotonic() + timeout
    while True:
        value = driver.execute_script(f"const s = window.viewerState; return s ? ({script}) : null;")
        if value:
            return value
        if time.monotonic() > deadline:
            state = driver.execute_script("return window.viewerState")
            error = driver.execute_script("const e = document.getElementById('error'); return e ? e.textContent : ''")
            raise Failure(f"timed out after {timeout:.0f} s waiting for {what}; viewerState={state}"
                          + (f"; page error: {error}" if error else ""))
        time.sleep(0.05)


def wait_frames(driver, count, timeout):
    start = driver.execute_script("return window.viewerState.frames")
    wait_for(driver, f"{count} more frames", f"s.frames >= {start + count}", timeout)


def canvas_png(driver):
    from selenium.webdriver.common.by import By
    return driver.find_element(By.CSS_SELECTOR, "#stage canvas").screenshot_as_png


def get_url(url):
    with urllib.request.urlopen(url, timeout=30) as response:
        return response.read()


def first_training_view(views, test_every):
    """train-rgb's first training view: by name, the first whose index is not a multiple of test_every."""
    by_name = sorted(views, key=lambda v: v["name"])
    held_out = [v["name"] for k, v in enumerate(by_name) if test_every > 0 and k % test_every == 0]
    marked = [v["name"] for v in by_name if v.get("test")]
    if marked != held_out:
        raise Failure(f"/api/model marks {marked} as test views; every {test_every}th by name is {held_out}")
    train = [v for v in by_name if v["name"] not in held_out]
    if not train:
        raise Failure("/api/model has no training view")
    return train[0]


def camera_errors(cam, view):
    """How far the page's camera is from the view: position, rotation (max |element|) and projection."""
    x, y, z, w = cam["quaternion"]
    # three.js camera-to-world rotation (looking down -z, y up); its columns must be the view's camera
    # axes in world coordinates, R's rows (OpenCV: x right, y down, z forward) with y and z negated.
    m = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    R = view["R"]
    sign = (1, -1, -1)
    rotation = max(abs(m[i][c] - sign[c] * R[3 * c + i]) for i in range(3) for c in range(3))
    position = max(abs(a - b) for a, b in zip(cam["position"], view["center"]))
    P = cam["projection"]  # column-major
    w_, h_ = view["width"], view["height"]
    want = {0: 2 * view["fx"] / w_, 5: 2 * view["fy"] / h_, 8: 1 - 2 * view["cx"] / w_, 9: 2 * view["cy"] / h_ - 1}
    projection = max(abs(P[k] - v) for k, v in want.items())
    return position, rotation, projection


def check_first_view(driver, url, args, failures):
    """The view the page opens at: the first training camera, showing the building."""
    from PIL import Image, ImageChops, ImageStat
    model = json.loads(get_url(url + "api/model"))
    view = first_training_view(model["views"], args.test_every)
    wait_frames(driver, 3, args.timeout)
    png = canvas_png(driver)
    if args.first_screenshot:
        driver.save_screenshot(args.first_screenshot)
        print(f"first-view screenshot: {args.first_screenshot}")
    state = driver.execute_script("return window.viewerState")
    cam = driver.execute_script("return window.viewerCamera ? window.viewerCamera() : null")
    hide = driver.execute_script("const b = document.getElementById('farsplats-toggle');"
                                 "return b ? b.getAttribute('aria-pressed') : null")
    if hide != "true":
        failures.append(f"'hide far splats' is not on by default (aria-pressed {hide!r})")
    # The photo beside the render as the calibration saw it: the browser must not apply EXIF Orientation.
    orientation = driver.execute_script("const p = document.getElementById('view-photo');"
                                        "return p ? getComputedStyle(p).imageOrientation : null")
    if orientation != "none":
        failures.append(f"the view's photo is shown with image-orientation {orientation!r}, not 'none': a phone "
                        "photo's EXIF Orientation would turn it away from its camera")
    hidden = state.get("hidden") or 0
    if not 0 < hidden <= args.max_hidden * model["gaussians"]:
        failures.append(f"{hidden} of {model['gaussians']} splats hidden as far: expected some (the sky), "
                        f"at most {100 * args.max_hidden:g}%")
    print(f"first view: page {state.get('firstView')!r} (camera {cam and cam.get('view')!r}), "
          f"first training view {view['name']!r}; far splats hidden: {state.get('hidden')}")
    if not cam:
        failures.append("the page has no window.viewerCamera(): cannot read its camera")
    else:
        if cam["view"] != view["name"] or state.get("view") != view["name"]:
            failures.append(f"the page opens at {cam['view'] or 'a free camera'}, not the first training view "
                            f"{view['name']}")
        position, rotation, projection = camera_errors(cam, view)
        scale = max(1.0, *(abs(c) for c in view["center"]))
        print(f"first view's camera vs {view['name']}: position {position:.2e}, rotation {rotation:.2e}, "
              f"projection {projection:.2e}")
        if position > 1e-6 * scale or rotation > 1e-5 or projection > 1e-6:
            failures.append(f"the first camera is not {view['name']}'s pose and intrinsics (position off by "
                            f"{position:.3g}, rotation by {rotation:.3g}, projection by {projection:.3g})")

    render = Image.open(io.BytesIO(png)).convert("RGB")
    if abs(render.width / render.height / (view["width"] / view["height"]) - 1) > 0.02:
        failures.append(f"the first canvas ({render.width} x {render.height}) does not show {view['name']}'s aspect "
                        f"ratio ({view['width']} x {view['height']})")
    # Non-background share of the central half: empty where nothing, or only far splats, cover it.
    w, h = render.size
    centre = render.crop((w // 4, h // 4, w - w // 4, h - h // 4))
    diff = ImageChops.difference(centre, Image.new("RGB", centre.size, BACKGROUND))
    r, g, b = diff.split()
    filled = ImageChops.lighter(ImageChops.lighter(r, g), b).point(lambda v: 255 if v > 16 else 0)
    filled_share = ImageStat.Stat(filled).mean[0] / 255
    # The render against the photo on the city model's pixels: a training view reproduces its photo.
    photo = Image.open(io.BytesIO(get_url(url + view["image"].lstrip("/")))).convert("RGB")
    stem = os.path.splitext(view["name"])[0]
    labels = Image.open(os.path.join(args.labels, stem, "level3.png")).convert("I").resize(photo.size, Image.NEAREST)
    mask = Image.new("L", photo.size)
    mask.putdata([255 if v > 0 else 0 for v in labels.getdata()])
    object_share = ImageStat.Stat(mask).mean[0] / 255
    error = ImageChops.difference(render.resize(photo.size, Image.BILINEAR), photo)
    mean_error = sum(ImageStat.Stat(error, mask).mean) / 3 if object_share > 0 else float("inf")
    print(f"first view: {100 * filled_share:.1f}% of the central pixels covered; city model on "
          f"{100 * object_share:.1f}% of the photo, mean |render - photo| there {mean_error:.1f}")
    if filled_share < args.min_first_centre:
        failures.append(f"the first view's centre is {100 * (1 - filled_share):.0f}% empty background "
                        f"(> {100 * (1 - args.min_first_centre):.0f}%): the building is not in view")
    if mean_error > args.max_first_error:
        failures.append(f"the first view does not show {view['name']}'s photo: mean |render - photo| {mean_error:.1f} "
                        f"> {args.max_first_error:g} on the city model's pixels")


def highlighted_on_class(before_png, after_png, labels, label_value, min_change):
    """(highlighted pixels, of them on the class) at the label map's resolution."""
    from PIL import Image, ImageChops
    before = Image.open(io.BytesIO(before_png)).convert("RGB")
    after = Image.open(io.BytesIO(after_png)).convert("RGB")
    if before.size != after.size:
        raise Failure(f"the canvas changed size during the query: {before.size} -> {after.size}")
    canvas_aspect = after.width / after.height
    label_aspect = labels.width / labels.height
    if abs(canvas_aspect / label_aspect - 1) > 0.02:
        raise Failure(f"the canvas ({after.width} x {after.height}) does not show the view's aspect ratio "
                      f"({labels.width} x {labels.height})")
    diff = ImageChops.difference(before, after).resize(labels.size, Image.NEAREST)
    r, g, b = diff.split()
    changed = ImageChops.lighter(ImageChops.lighter(r, g), b).point(lambda v: 255 if v > min_change else 0)
    highlighted = on_class = 0
    for c, label in zip(changed.getdata(), labels.getdata()):
        if c:
            highlighted += 1
            on_class += label == label_value
    return highlighted, on_class


def check(args, url, failures):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select
    labels, label_value = load_labels(args)
    driver = start_browser()
    try:
        started = time.monotonic()
        driver.get(url)
        wait_for(driver, "the splats (viewerState.ready)", "s.ready", args.timeout)
        status = driver.find_element(By.ID, "status").text
        print(f"loaded in {time.monotonic() - started:.1f} s ({status})")
        warning = driver.find_element(By.ID, "warning")
        if warning.is_displayed():
            print(f"warning banner: {warning.text}")
        check_first_view(driver, url, args, failures)

        views = [o.get_attribute("value") for o in Select(driver.find_element(By.ID, "view-select")).options]
        if args.view not in views:
            raise Failure(f"view '{args.view}' is not in #view-select (has: {', '.join(v for v in views if v)})")
        Select(driver.find_element(By.ID, "view-select")).select_by_value(args.view)
        wait_for(driver, f"view {args.view}", f"s.view === {json.dumps(args.view)}", args.timeout)
        wait_frames(driver, 3, args.timeout)
        before = canvas_png(driver)

        Select(driver.find_element(By.ID, "mode")).select_by_value(args.mode)
        Select(driver.find_element(By.ID, "level")).select_by_value(str(args.level))
        if args.threshold is not None:
            driver.execute_script("const t = document.getElementById('threshold'); t.value = arguments[0];"
                                  "t.dispatchEvent(new Event('input'));", args.threshold)
        box = driver.find_element(By.ID, "query")
        box.clear()
        started = time.monotonic()
        box.send_keys(args.query + Keys.ENTER)
        query = wait_for(driver, "the query to be applied",
                         f"(s.query && s.query.text === {json.dumps(args.query)} && (s.query.applied || s.query.error))"
                         " ? s.query : null", args.timeout)
        if query.get("error"):
            raise Failure(f"the query failed: {query['error']}")
        applied = time.monotonic() - started
        wait_frames(driver, 3, args.timeout)
        print(f"query '{args.query}' applied in {applied:.2f} s: level {query['level']}, "
              f"{query['selected']} Gaussians selected")
        after = canvas_png(driver)
        if args.screenshot:
            driver.save_screenshot(args.screenshot)
            print(f"screenshot: {args.screenshot}")

        # Every cell of the object table lies inside the side panel (long ids must not push a column out).
        overflow = driver.execute_script(
            "const side = document.getElementById('side').getBoundingClientRect(); let worst = -Infinity;"
            "for (const row of document.querySelectorAll('#objects tr'))"
            "  for (const cell of row.cells) worst = Math.max(worst, cell.getBoundingClientRect().right - side.right);"
            "return worst;")
        print(f"object table: its rightmost cell ends {-overflow:.0f} px inside the side panel")
        if overflow > 0:
            failures.append(f"the object table overflows the side panel by {overflow:.0f} px: its last column is cut")

        highlighted, on_class = highlighted_on_class(before, after, labels, label_value, args.min_change)
        total = labels.width * labels.height
        fraction = on_class / highlighted if highlighted else 0.0
        print(f"highlighted pixels: {highlighted} of {total} ({100 * highlighted / total:.1f}%) at "
              f"{labels.width} x {labels.height}; on '{args.cls}': {on_class} ({100 * fraction:.1f}%)")
        if highlighted < args.min_pixels * total:
            failures.append(f"only {highlighted} highlighted pixels (< {100 * args.min_pixels:.1f}% of {total})")
        if fraction < args.min_fraction:
            failures.append(f"{100 * fraction:.1f}% of the highlighted pixels are on '{args.cls}' "
                            f"(< {100 * args.min_fraction:.0f}%)")

        severe = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
        for entry in severe:
            print(f"console SEVERE: {entry.get('message')}")
        if severe:
            failures.append(f"{len(severe)} SEVERE console entries")
    finally:
        driver.quit()


def main():
    args = parse_args()
    require_tools()
    failures = []
    proc = None
    try:
        if args.server_url:
            url = args.server_url.rstrip("/") + "/"
        else:
            proc, url = start_server(args)
            print(f"server: {url}")
        check(args, url, failures)
    except Failure as e:
        failures.append(str(e))
    finally:
        if proc and args.keep_server:
            print(f"server left running: {url} (pid {proc.pid})")
        elif proc:
            stop_server(proc)
    if failures:
        for f in failures:
            print(f"FAIL: {f}")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
