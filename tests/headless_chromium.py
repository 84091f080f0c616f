"""Headless Chromium for the browser tests (tests/report/browser_check.py, tests/viewer/browser_query_check.py):
Debian's chromium and chromedriver driven by Selenium under Debian's /usr/bin/python3.

A missing piece (Chromium, chromedriver, Selenium, PIL) skips the test: exit 77, which CTest's
SKIP_RETURN_CODE reports as skipped.
"""
import os
import shutil
import sys

SKIP = 77
CHROMEDRIVER = "/usr/bin/chromedriver"

# No GPU here: WebGL2 runs on SwiftShader through ANGLE. Without --enable-unsafe-swiftshader, Chromium 156
# only falls back to it with a deprecation warning (later versions drop the fallback).
FLAGS = ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--window-size=1400,1000", "--hide-scrollbars",
         "--force-device-scale-factor=1")


def skip(why):
    print(f"SKIPPED: {why}")
    sys.exit(SKIP)


def require_tools():
    """Skips (exit 77) unless PIL, Selenium, Chromium and chromedriver are all there."""
    try:
        import PIL  # noqa: F401
    except ImportError:
        skip("PIL is not installed for this python (Debian: apt-get install python3-pil)")
    try:
        import selenium  # noqa: F401
    except ImportError:
        skip("Selenium is not installed for this python (Debian: apt-get install python3-selenium)")
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser or not os.access(CHROMEDRIVER, os.X_OK):
        skip("Chromium or chromedriver is not installed (Debian: apt-get install chromium chromium-driver)")


def start_browser():
    """A headless Chromium whose console log the caller can read (driver.get_log('browser'))."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    for flag in FLAGS:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(executable_path=CHROMEDRIVER), options=options)
