r"""Open the built docs site and the workflow report in a real headless browser.

Serves each directory over HTTP on localhost, opens every page of the site (the API
reference's generated pages excepted: two of them are opened as samples) and the report in
Debian's chromium through chromedriver (selenium); in the report it walks every category
and opens every result's preview. It fails if a page or a preview has

* an image that did not load (``naturalWidth == 0`` once the page is complete), or
* a script error, or a request to the site itself that failed, in the browser's console
  (level SEVERE), or
* (a docs page) any request to another host, whether it succeeded or not: the site must
  read the same with no network (the browser's network log lists every request), or
* (a docs page with math) math that MathJax did not typeset: a formula left as raw TeX
  (``\(``, ``$$``) in the page's text, or fewer rendered formulas than the page has.

In the workflow's report a failed request to another host is listed but is not a failure.

Keeps a screenshot of the site's front page and of the report (``--screenshots DIR``).

Usage: python .ci/browser_check.py --site docs/_build/html [--report results/report.html]
       [--screenshots ci-artifacts]
Exits 1 listing every problem, 0 if none.
"""

from __future__ import annotations

import argparse
import functools
import http.server
import json
import threading
import time
from contextlib import contextmanager
from pathlib import Path
from urllib.parse import urlsplit

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"

#: JavaScript: the images of the page that have not loaded.
BROKEN_IMAGES = """
return Array.from(document.images)
    .filter(img => img.complete && img.naturalWidth === 0 && img.src)
    .map(img => img.src);
"""


@contextmanager
def serve(root: Path):
    """An HTTP server on a free localhost port serving ``root``; yields its base URL."""

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args: object) -> None:
            pass

    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(Quiet, directory=str(root))
    )
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()


def browser() -> webdriver.Chrome:
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,1000"):
        options.add_argument(arg)
    # the performance log holds the DevTools network events: every request a page makes
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


def console_problems(driver: webdriver.Chrome, url: str, base: str) -> list[str]:
    """SEVERE console entries of the page: script errors and the site's own failed
    requests; another host's failed requests are printed as notes."""
    problems = []
    for entry in driver.get_log("browser"):
        if entry["level"] != "SEVERE":
            continue
        message = entry["message"]
        source = message.split(" ", 1)[0]
        if source == f"{base}/favicon.ico":
            continue  # the browser's own request for a page without an icon
        if "Failed to load resource" in message and not source.startswith(base):
            print(f"note: {url}: another host was not reached: {source}")
            continue
        problems.append(f"{url}: console error: {message}")
    return problems


def requested_urls(driver: webdriver.Chrome) -> list[str]:
    """Every URL the browser requested since the last call (its network log)."""
    urls = []
    for entry in driver.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message.get("method") == "Network.requestWillBeSent":
            urls.append(message["params"]["request"]["url"])
    return urls


def other_hosts(urls: list[str], base: str) -> list[str]:
    """The URLs of ``urls`` that go to a host other than ``base``'s (``data:`` and
    ``blob:`` URLs are the page's own content)."""
    here = urlsplit(base).netloc
    return [u for u in urls if urlsplit(u).scheme in ("http", "https", "ws", "wss", "ftp")
            and urlsplit(u).netloc != here]  # fmt: skip


#: JavaScript (async): wait for MathJax's typesetting, then count the math the page has,
#: the formulas MathJax rendered, and raw TeX left in the visible text.
MATH_STATE = r"""
const done = arguments[arguments.length - 1];
const count = () => {
    const text = document.body.innerText;
    done({
        math: document.querySelectorAll("span.math, div.math").length,
        rendered: document.querySelectorAll("mjx-container").length,
        raw: ["\\(", "\\[", "$$"].filter(s => text.includes(s)),
        mathjax: typeof window.MathJax !== "undefined" && !!window.MathJax.startup,
    });
};
if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    MathJax.startup.promise.then(count, count);
} else {
    count();
}
"""


def math_problems(driver: webdriver.Chrome, url: str) -> list[str]:
    """Math left as raw TeX on the page (MathJax did not load or did not typeset)."""
    driver.set_script_timeout(30)
    state = driver.execute_async_script(MATH_STATE)
    if not state["math"]:
        return []
    problems = []
    if not state["mathjax"]:
        problems.append(f"{url}: has {state['math']} formulas but MathJax did not load")
    elif state["rendered"] < state["math"]:
        problems.append(f"{url}: MathJax rendered {state['rendered']} of {state['math']} formulas")
    if state["raw"]:
        problems.append(f"{url}: raw TeX visible ({', '.join(state['raw'])})")
    return problems


def check_page(driver: webdriver.Chrome, url: str, base: str, offline: bool = False) -> list[str]:
    """Problems of one page: broken images and console errors; with ``offline`` also any
    request to another host, and math that was not typeset."""
    requested_urls(driver)  # drop the log of the pages before
    driver.get(url)
    deadline = time.monotonic() + 20
    while driver.execute_script("return document.readyState") != "complete":
        if time.monotonic() > deadline:
            return [f"{url}: did not finish loading in 20 s"]
        time.sleep(0.05)
    problems = [f"{url}: image did not load: {src}" for src in driver.execute_script(BROKEN_IMAGES)]
    if offline:
        problems += math_problems(driver, url)
        problems += [
            f"{url}: request to another host: {u}"
            for u in other_hosts(requested_urls(driver), base)
        ]
    return problems + console_problems(driver, url, base)


#: Entries of the report's sidebar that are not result categories.
REPORT_GENERAL = ("Workflow", "Statistics", "About")


def _open_report_at(driver: webdriver.Chrome, url: str, path: list[str]) -> None:
    """Load the report and click through the categories in ``path``."""
    driver.get(url)
    _wait_for(driver, "//li/a")
    for name in path:
        xpath = f"//li[not(ancestor::ol)]/a[normalize-space()={name!r}]"
        _wait_for(driver, xpath)  # the sidebar renders after the click before
        _click(driver, driver.find_element(By.XPATH, xpath))
    # the view of the last category: its breadcrumb shows it
    if path:
        _wait_for(driver, f"//ol//a[normalize-space()={path[-1]!r}]")
    time.sleep(0.3)


def _click(driver: webdriver.Chrome, element: object) -> None:
    """Click through the DOM, as the report's own handlers see it (a pointer click can be
    intercepted by the sidebar's transition)."""
    driver.execute_script("arguments[0].click();", element)


def _wait_for(driver: webdriver.Chrome, xpath: str, seconds: float = 20.0) -> None:
    deadline = time.monotonic() + seconds
    while not driver.find_elements(By.XPATH, xpath):
        if time.monotonic() > deadline:
            raise TimeoutError(f"{xpath} did not appear in {seconds:g} s")
        time.sleep(0.1)


def check_report(driver: webdriver.Chrome, url: str, base: str) -> tuple[list[str], int]:
    """Walk every category of a Snakemake report and open every result's preview;
    problems (broken images, console errors) and the number of results opened."""
    problems: list[str] = []
    opened = 0
    paths: list[list[str]] = [[]]
    while paths:
        path = paths.pop()
        where = f"{url} [{' / '.join(path) or 'front page'}]"
        try:
            _open_report_at(driver, url, path)
        except TimeoutError as exc:
            problems.append(f"{where}: the view did not open ({exc})")
            problems += console_problems(driver, where, base)
            continue
        problems += console_problems(driver, where, base)
        names = [
            a.text.strip()
            for a in driver.find_elements(By.XPATH, "//li[not(ancestor::ol)]/a")
            if a.text.strip() and a.text.strip() not in REPORT_GENERAL
        ]
        paths += [[*path, n] for n in names if n not in path]
        rows = len(driver.find_elements(By.XPATH, "//tr[td]"))
        for i in range(rows):
            _open_report_at(driver, url, path)
            row = driver.find_elements(By.XPATH, "//tr[td]")[i]
            label = " / ".join([*path, row.find_element(By.TAG_NAME, "td").text])
            _click(driver, row.find_element(By.XPATH, ".//a[@iconname='eye']"))
            time.sleep(0.3)
            opened += 1
            problems += [
                f"{url} [{label}]: image did not load: {src[:60]}"
                for src in driver.execute_script(BROKEN_IMAGES)
            ]
            problems += console_problems(driver, f"{url} [{label}]", base)
    return problems, opened


def site_pages(site: Path) -> list[str]:
    pages = sorted(p.relative_to(site).as_posix() for p in site.rglob("*.html"))
    api = [p for p in pages if p.startswith("api/generated/")]
    # every page, but of the generated API pages (they share two templates) only the first
    # and the page of pencore.simulate
    sample = {*api[:1], *(p for p in api if p.endswith("/pencore.simulate.html"))}
    return [p for p in pages if not p.startswith(("api/generated/", "_"))] + sorted(sample)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--site", type=Path, required=True, help="the built HTML site")
    parser.add_argument("--report", type=Path, help="the workflow's HTML report")
    parser.add_argument("--screenshots", type=Path, default=Path("ci-artifacts"))
    args = parser.parse_args(argv)
    args.screenshots.mkdir(parents=True, exist_ok=True)
    problems: list[str] = []
    driver = browser()
    try:
        with serve(args.site) as base:
            pages = site_pages(args.site)
            math_pages = 0
            for page in pages:
                problems += check_page(driver, f"{base}/{page}", base, offline=True)
                html = (args.site / page).read_text(errors="replace")
                math_pages += 'class="math notranslate' in html
            driver.get(f"{base}/index.html")
            driver.save_screenshot(str(args.screenshots / "docs-front-page.png"))
            print(
                f"browser check: {len(pages)} pages of {args.site} ({math_pages} with math), "
                "no request to another host allowed"
            )
            if not math_pages:
                problems.append(f"{args.site}: no page with math was checked")
        if args.report:
            with serve(args.report.parent) as base:
                url = f"{base}/{args.report.name}"
                problems += check_page(driver, url, base)
                driver.save_screenshot(str(args.screenshots / "report.png"))
                found, opened = check_report(driver, url, base)
                problems += found
                print(f"browser check: {args.report}, {opened} results opened")
    finally:
        driver.quit()
    for problem in problems:
        print(problem)
    print(f"browser check: {len(problems)} problem(s); screenshots in {args.screenshots}/")
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
