#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
"""The perceptual experiment end to end in headless Chromium (Selenium + chromedriver, Debian's packages).

usage: perceptual_browser.py STIPPLE_VALIDATE MATRIX WORK [SCREENSHOTS]

Runs the matrix (its 'perceptual' section makes the experiment folder), copies the experiment out of the report,
serves it with --serve-study and drives the page as simulated observers (keyboard and mouse):

  recovery   12 observers with a known latent quality per pattern (JOD, 1.5 apart) and Thurstone Case V noise: the
             scaling orders the patterns as the latent scores do (probability about 0.99 per set, by simulation of
             the same observers), and of the 4 relative scores' 95% intervals at least 3 cover the truth (each
             covers with probability ≥ 0.95: two or more misses have probability ≤ 0.014).
  careless   one observer answering at random everywhere: excluded by the control (a random ranking passes one
             control with probability 1/4 here, both with 1/16; seed fixed).
  null       10 observers who see no difference between the patterns (but see the control): at most 1 of the 6
             pairs separated (each pair is separated by chance with probability 0.05: 2 or more with 0.033).
  hostile    malformed JSON, a huge body, a wrong study id, a wrong observer id, path tricks, a second submission
             of one observer: a clear refusal, and the votes already collected unchanged byte for byte.
  download   one observer from file:// (no server): the page downloads its votes file, which --analyse-study merges.
  report     --merge of the run's report with --study fills the report's perceptual block and Figure 8.

All randomness is seeded; every assertion names what failed. Exit status 0 only when everything holds.
"""
import hashlib
import json
import os
import random
import shutil
import subprocess
import sys
import time
import urllib.error
import urllib.request

from selenium.webdriver.common.by import By

# The observer driver is the one researchers run (validation/perceptual/simulated_observers.py).
sys.dont_write_bytecode = True  # nothing written into the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "perceptual"))
from simulated_observers import browser, latent_chooser, run_session, start_server, stop_server  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def analyse(tool, folder, *extra):
    r = subprocess.run([tool, "--analyse-study", folder, *extra], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("--analyse-study failed: " + r.stderr)
    print(r.stdout)
    with open(os.path.join(folder, "analysis", "analysis.json")) as f:
        return json.load(f)


def request(url, body=None, ctype="application/json"):
    req = urllib.request.Request(url, data=body, method="POST" if body is not None else "GET",
                                 headers={"Content-Type": ctype})
    try:
        with urllib.request.urlopen(req, timeout=10) as r:
            return r.status, r.read().decode(errors="replace")
    except urllib.error.HTTPError as e:
        return e.code, e.read().decode(errors="replace")


def folder_digest(folder):
    h = hashlib.sha256()
    for name in sorted(os.listdir(folder)):
        h.update(name.encode())
        with open(os.path.join(folder, name), "rb") as f:
            h.update(f.read())
    return h.hexdigest()


def main():
    tool, matrix, work = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    shots = sys.argv[4] if len(sys.argv) > 4 else None
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    report = os.path.join(work, "report")
    r = subprocess.run([tool, matrix, "-o", report, "--cache", os.path.join(work, "cache"), "--threads", "2", "-q"],
                       capture_output=True, text=True)
    check(r.returncode in (0, 1), f"the run makes its report (exit {r.returncode}) {r.stderr.strip()[:300]}")
    made = os.path.join(report, "perceptual-study")
    check(os.path.isfile(os.path.join(made, "index.html")), "the run writes the experiment folder")
    with open(os.path.join(made, "key.json")) as f:
        key = json.load(f)
    page = open(os.path.join(made, "index.html")).read()
    for s in key["sets"]:
        for c in s["crops"]:
            check(c["pattern"] not in page, f"the page does not name pattern {c['pattern']}")
            break
    check("http://" not in page and "https://" not in page and "src=\"//" not in page,
          "the page loads nothing from the network")
    r = subprocess.run([tool, "--serve-study", made, "--port", "0"], capture_output=True, text=True, timeout=20)
    check(r.returncode == 3 and "inside a report folder" in r.stderr,
          "--serve-study refuses an experiment inside a report folder (the next run replaces it)")

    names = [s["name"] for s in key["sets"]]
    patterns = [c["pattern"] for c in key["sets"][0]["crops"]]
    latent = {names[0]: {patterns[0]: 0.0, patterns[1]: 1.5, patterns[2]: 3.0},
              names[1]: {patterns[0]: 0.0, patterns[1]: 3.0, patterns[2]: 1.5}}

    # --- recovery and careless, through the server ---
    study = os.path.join(work, "study")
    shutil.copytree(made, study)
    server, url = start_server(tool, study)
    driver = browser(1280, 800)
    try:
        # The order is the observer id's: the same id twice gives the same trials, another id others.
        driver.get(url + "?observer=x")
        a = driver.execute_script("return JSON.stringify(makeTrials('obs-1'))")
        b = driver.execute_script("return JSON.stringify(makeTrials('obs-1'))")
        c = driver.execute_script("return JSON.stringify(makeTrials('obs-2'))")
        check(a == b and a != c, "trial order is reproducible per observer id and differs between ids")
        if shots:
            driver.save_screenshot(os.path.join(shots, "perceptual-intro-1280.png"))
        rng = random.Random(20261201)
        for i in range(12):
            status = run_session(driver, url, f"observer-{i + 1:02d}", latent_chooser(key, latent, rng),
                                 use_keys=i % 2 == 0)
            check(status == "ok", f"observer-{i + 1:02d}'s votes stored by the server ({status})")
        status = run_session(driver, url, "careless", latent_chooser(key, latent, random.Random(7), careless=True),
                             use_keys=False)
        check(status == "ok", "the careless observer's votes stored")
        # A server killed during a session loses that session only.
        votes_dir = os.path.join(study, "votes")
        before = folder_digest(votes_dir)
        driver.get(url + "?observer=interrupted")
        driver.find_element(By.ID, "start").click()
        driver.find_element(By.TAG_NAME, "body").send_keys("1")
        server.kill()
        server.wait()
        check(folder_digest(votes_dir) == before and len(os.listdir(votes_dir)) == 13,
              "a server killed during a session leaves the 13 finished observers' votes intact")
        server, url = start_server(tool, study)
        # The pixels: integer zoom, pixelated, at 1280 and 800 px wide.
        for width in (1280, 800):
            driver.set_window_size(width, 800)
            driver.get(url + "?observer=zoom")
            driver.find_element(By.ID, "start").click()
            time.sleep(0.3)
            info = driver.execute_script(
                "return [...document.querySelectorAll('#crops img')].map(i => [i.naturalWidth, i.getBoundingClientRect().width,"
                " Number(i.dataset.zoom), getComputedStyle(i).imageRendering, i.getBoundingClientRect().right])")
            ok = all(n > 0 and abs(w - n * z) < 1e-6 and z >= 1 and r == "pixelated" and right <= width
                     for n, w, z, r, right in info)
            check(ok, f"crops at an integer zoom, pixelated, inside the window at {width} px: {info}")
            if shots:
                driver.save_screenshot(os.path.join(shots, f"perceptual-trial-{width}.png"))
    finally:
        driver.quit()

    # --- hostile requests: each refused, the collected votes unchanged ---
    before = folder_digest(votes_dir)
    with open(os.path.join(votes_dir, "observer-01.json"), "rb") as f:
        good = json.loads(f.read())
    wrong_study = dict(good, study="0000000000000000", observer="someone-else")
    wrong_id = dict(good, observer="../../evil")
    bad_crop = json.loads(json.dumps(good))
    bad_crop["observer"] = "bad-crop"
    bad_crop["trials"][0]["ranking"][0] = "../key"
    hostile = [
        ("malformed JSON", request(url + "votes", b"{\"format\": ")),
        ("a body over the limit", request(url + "votes", b"{" + b" " * (2 * 1024 * 1024) + b"}")),
        ("votes of another study", request(url + "votes", json.dumps(wrong_study).encode())),
        ("a path as observer id", request(url + "votes", json.dumps(wrong_id).encode())),
        ("a crop id not of the set", request(url + "votes", json.dumps(bad_crop).encode())),
        ("observer-01 submitting again", request(url + "votes", json.dumps(dict(good, finished="later")).encode())),
    ]
    for what, (code, text) in hostile:
        check(400 <= code < 500 and text.strip() != "", f"{what}: refused with {code}: {text.strip()[:120]}")
    for path in ("key.json", "crops/../key.json", "crops/%2e%2e/key.json", "votes/observer-01.json",
                 "..%2fkey.json", "crops/zz.png"):
        code, _ = request(url + path)
        check(code == 404, f"GET /{path}: {code} (only the page and the crops are served)")
    check(folder_digest(votes_dir) == before, "the votes already collected are unchanged")
    check(server.poll() is None, "the server is still running after the hostile requests")
    stop_server(server)

    a = analyse(tool, study)
    careless = [o for o in a["observers"] if o["observer"] == "careless"][0]
    check(careless["excluded"] and "control" in careless["reason"],
          f"the careless observer is excluded by the control ({careless['reason']})")
    honest = [o for o in a["observers"] if o["observer"] != "careless"]
    check(all(not o["excluded"] for o in honest), "no simulated honest observer is excluded")
    check(a["included"] == 12, f"12 observers kept ({a['included']})")
    missed = 0
    for s in a["sets"]:
        truth = latent[s["name"]]
        got = sorted(s["crops"], key=lambda c: -c["jod"])
        want = sorted(truth, key=lambda p: -truth[p])
        check([c["pattern"] for c in got] == want, f"{s['name']}: people's order {[c['pattern'] for c in got]}"
              f" is the latent order {want}")
        for c in s["crops"][1:]:
            t = truth[c["pattern"]] - truth[s["crops"][0]["pattern"]]
            inside = c["lo95"] <= t <= c["hi95"]
            missed += not inside
            print(f"     {s['name']} {c['pattern']}: truth {t:+.2f}, {c['jod']:+.2f} [{c['lo95']:+.2f}, {c['hi95']:+.2f}]")
    check(missed <= 1, f"the 95% intervals cover the latent scores: {4 - missed} of 4 (at least 3 required)")

    # --- the null: no difference to see ---
    null = os.path.join(work, "null")
    shutil.copytree(made, null)
    server, url = start_server(tool, null)
    driver = browser(1280, 800)
    flat = {n: {p: 0.0 for p in patterns} for n in names}
    try:
        rng = random.Random(99)
        for i in range(10):
            run_session(driver, url, f"null-{i + 1:02d}", latent_chooser(key, flat, rng), use_keys=i % 2 == 1)
    finally:
        driver.quit()
        stop_server(server)
    a = analyse(tool, null)
    separated = sum(p["verdict"] in ("a", "b") for s in a["sets"] for p in s["pairs"])
    check(a["included"] >= 9, f"null: observers kept ({a['included']} of 10; each is left out with probability 1/36)")
    check(separated <= 1, f"null: {separated} of 6 pairs separated (at most 1 allowed)")

    # --- the page's own download from file:// ---
    downloads = os.path.join(work, "downloads")
    os.makedirs(downloads)
    driver = browser(800, 700, downloads)
    try:
        driver.get("file://" + os.path.join(study, "index.html") + "?observer=look")
        driver.find_element(By.ID, "start").click()
        time.sleep(0.3)
        loaded = driver.execute_script(
            "return [...document.querySelectorAll('#crops img')].every(i => i.complete && i.naturalWidth > 0)")
        check(loaded, "from file:// the crops load (no server, no network)")
        run_session(driver, "file://" + os.path.join(study, "index.html"), "offline-1",
                    latent_chooser(key, latent, random.Random(5)), use_keys=True)
        target = os.path.join(downloads, "votes-offline-1.json")
        for _ in range(100):
            if os.path.exists(target):
                break
            time.sleep(0.1)
        check(os.path.exists(target), "from file:// the page downloads votes-offline-1.json")
        if shots:
            driver.save_screenshot(os.path.join(shots, "perceptual-done-800.png"))
    finally:
        driver.quit()
    a = analyse(tool, study, downloads)
    check(any(o["observer"] == "offline-1" and not o["excluded"] for o in a["observers"]) and a["included"] == 13,
          f"--analyse-study merges the downloaded file ({a['included']} kept)")
    dup = subprocess.run([tool, "--analyse-study", study, downloads, downloads], capture_output=True, text=True)
    check(dup.returncode == 3 and "already voted" in dup.stderr, "an observer's votes given twice are refused")
    broken = os.path.join(work, "broken")
    os.makedirs(broken)
    with open(os.path.join(broken, "x.json"), "w") as f:
        f.write("{\"format\": \"stipple-perceptual-votes\", \"version\": 1, \"study\": ")
    r = subprocess.run([tool, "--analyse-study", study, broken], capture_output=True, text=True)
    check(r.returncode == 3 and "x.json" in r.stderr and "not JSON" in r.stderr,
          f"a malformed votes file is named: {r.stderr.strip()[:160]}")

    # --- the report: --merge of the run with --study ---
    people = os.path.join(work, "report-people")
    r = subprocess.run([tool, matrix, "--merge", report, "--study", study, "-o", people, "-q"],
                       capture_output=True, text=True)
    check(r.returncode in (0, 1), f"--merge with --study writes the report (exit {r.returncode}) {r.stderr[:300]}")
    html = open(os.path.join(people, "index.html")).read()
    check('id="perceptual-verdicts"' in html and 'id="figure-8"' in html,
          "the report's first screen has people's verdicts and Figure 8")
    check('<span class="people">people: ' in html,
          "the study table's perceptual column carries people's verdict beside mean FLIP's")
    check(all(os.path.exists(os.path.join(people, "plots", f"perceptual-set-{i + 1}.png")) for i in range(len(names))),
          "Figure 8's plots are written")
    for i, s in enumerate(key["sets"]):
        rows = [l.split() for l in open(os.path.join(people, "plots", f"perceptual-set-{i + 1}.dat")) if l[0] != "#"]
        check([r[1].strip('"') for r in rows] == [c["pattern"] for c in s["crops"]] and all(len(r) == 5 for r in rows),
              f"Figure 8's data for set {i + 1}: one row per pattern with score and interval ({rows})")
    if shots:
        driver = browser(1280, 1000)
        try:
            driver.get("file://" + os.path.join(people, "index.html#perceptual"))
            time.sleep(0.5)
            driver.save_screenshot(os.path.join(shots, "perceptual-report-1280.png"))
        finally:
            driver.quit()

    print(f"{len(failures)} failed" if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
