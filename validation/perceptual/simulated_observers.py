#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
"""Simulated observers: the experiment page driven in headless Chromium (Selenium + chromedriver, Debian's
python3-selenium and chromium-driver), one session per observer, against a served experiment folder.

usage: simulated_observers.py FOLDER URL [--observers N] [--careless N] [--truth flip|none] [--spread JOD]
                              [--seed S] [--prefix NAME] [--width PX] [--height PX]

FOLDER is the experiment folder that `stipple-validate --serve-study FOLDER` serves at URL (the page's address it
prints); the observers' votes end up in FOLDER/votes/ as the server stores them. The script reads FOLDER/key.json
(which crop is which pattern: the page never loads it) to give each observer a latent quality per pattern:

  --truth flip   (default) people see what mean FLIP sees: per set, the crop with the lowest mean FLIP is `--spread`
                 JOD (default 1.5, the spacing validation.perceptual_browser checks recovery at) above the one with
                 the highest, the others placed linearly between by FLIP. Far apart crops make 12 observers nearly
                 unanimous (3 JOD: 98% preference), where scaling by maximum likelihood overstates the distance.
  --truth none   no visible difference between the patterns (the null).

Each observer ranks a trial by latent quality plus Thurstone Case V noise (1 JOD = 75% preference), sees the control
crop (fewer samples) as clearly worst, and alternates keyboard and mouse. `--careless N` adds N observers who rank
at random (the control should exclude them). Everything is seeded (`--seed`). Prints each observer's status and
the latent scores used; the exit status is 0 when every session's votes were stored.

The module's functions are also what validation/tests/perceptual_browser.py drives its observers with.
"""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

SIGMA = 1.0 / 0.6744897501960817  # 1 JOD = 75% preference (Thurstone Case V, as the analysis)


def browser(width, height, download_dir=None):
    """Headless Chromium at a window of width x height CSS pixels (device scale 1)."""
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                f"--window-size={width},{height}", "--force-device-scale-factor=1"):
        options.add_argument(arg)
    if download_dir:
        options.add_experimental_option("prefs", {"download.default_directory": download_dir,
                                                  "download.prompt_for_download": False})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"),
                            options=options)


def run_session(driver, url, observer, choose, use_keys):
    """One observer's session. choose(crop_ids) -> ranking (best first) or None (no visible difference).
    Returns the page's submission status ("ok" when the server stored the votes)."""
    driver.get(url)
    box = driver.find_element(By.ID, "observer")
    box.clear()
    box.send_keys(observer)
    driver.find_element(By.ID, "start").click()
    while driver.find_element(By.ID, "trial").is_displayed():
        crops = driver.find_elements(By.CSS_SELECTOR, "#crops .crop")
        ids = [c.get_attribute("data-crop") for c in crops]
        ranking = choose(ids)
        if ranking is None:
            if use_keys:
                driver.find_element(By.TAG_NAME, "body").send_keys("0")
            else:
                driver.find_element(By.ID, "nodiff").click()
        else:
            for cid in ranking[:-1]:  # the last is filled in by the page
                i = ids.index(cid)
                if use_keys:
                    driver.find_element(By.TAG_NAME, "body").send_keys(str(i + 1))
                else:
                    crops[i].click()
        if use_keys:
            driver.find_element(By.TAG_NAME, "body").send_keys(Keys.ENTER)
        else:
            driver.find_element(By.ID, "next").click()
    body = driver.find_element(By.TAG_NAME, "body")
    for _ in range(100):
        if body.get_attribute("data-submitted") or url.startswith("file:"):
            break
        time.sleep(0.05)
    return body.get_attribute("data-submitted")


def latent_chooser(key, latent, rng, careless=False):
    """Rank by latent[set name][pattern] + Thurstone noise; the control (fewer samples) is seen as clearly worst.
    careless: a random ranking everywhere."""
    pattern_of, control_ids = {}, set()
    for s in key["sets"]:
        for c in s["crops"]:
            pattern_of[c["id"]] = (s["name"], c["pattern"])
        control_ids.add(s["control"]["id"])

    def choose(ids):
        if careless:
            return rng.sample(ids, len(ids))
        noisy = {}
        for cid in ids:
            if cid in control_ids:
                noisy[cid] = -100.0
            else:
                name, pattern = pattern_of[cid]
                noisy[cid] = latent[name][pattern] + rng.gauss(0, SIGMA / math.sqrt(2))
        return sorted(ids, key=lambda c: -noisy[c])
    return choose


def flip_truth(key, spread):
    """Per set: latent JOD linear in mean FLIP, the lowest FLIP `spread` above the highest (all 0 when equal)."""
    latent = {}
    for s in key["sets"]:
        flips = {c["pattern"]: c["flip"] for c in s["crops"]}
        if any(not isinstance(f, (int, float)) for f in flips.values()):
            raise SystemExit(f"key.json: set {s['name']}: a crop without a mean FLIP; use --truth none")
        lo, hi = min(flips.values()), max(flips.values())
        latent[s["name"]] = {p: (spread * (hi - f) / (hi - lo) if hi > lo else 0.0) for p, f in flips.items()}
    return latent


def start_server(tool, folder):
    """stipple-validate --serve-study FOLDER on a free port: (process, page URL)."""
    p = subprocess.Popen([tool, "--serve-study", folder, "--port", "0"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    line = p.stdout.readline()
    if "http://127.0.0.1:" not in line:
        p.kill()
        raise SystemExit("server did not start: " + line + p.stderr.read())
    return p, line.split(" at ")[1].split()[0]


def stop_server(p):
    p.terminate()
    try:
        p.wait(5)
    except subprocess.TimeoutExpired:
        p.kill()


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folder", help="the served experiment folder (its key.json gives the patterns)")
    ap.add_argument("url", help="the page's address printed by stipple-validate --serve-study")
    ap.add_argument("--observers", type=int, default=12)
    ap.add_argument("--careless", type=int, default=0)
    ap.add_argument("--truth", choices=("flip", "none"), default="flip")
    ap.add_argument("--spread", type=float, default=1.5, help="JOD between a set's best and worst FLIP (flip)")
    ap.add_argument("--seed", type=int, default=20261201)
    ap.add_argument("--prefix", default="simulated", help="observer ids: PREFIX-01, PREFIX-02, ...")
    ap.add_argument("--width", type=int, default=1280)
    ap.add_argument("--height", type=int, default=800)
    a = ap.parse_args(argv)
    if a.observers < 0 or a.careless < 0 or a.observers + a.careless == 0:
        ap.error("--observers and --careless: counts >= 0, at least one observer in all")
    with open(os.path.join(a.folder, "key.json"), encoding="utf-8") as f:
        key = json.load(f)
    latent = flip_truth(key, a.spread if a.truth == "flip" else 0.0)
    for name, scores in latent.items():
        print(f"latent {name}: " + ", ".join(f"{p} {v:+.2f} JOD" for p, v in scores.items()), flush=True)
    url = a.url if a.url.endswith("/") else a.url + "/"
    rng = random.Random(a.seed)
    stored = 0
    driver = browser(a.width, a.height)
    try:
        for i in range(a.observers + a.careless):
            careless = i >= a.observers
            observer = f"{a.prefix}-{'careless-' if careless else ''}{i + 1:02d}"
            status = run_session(driver, url, observer, latent_chooser(key, latent, rng, careless),
                                 use_keys=i % 2 == 0)
            stored += status == "ok"
            print(f"{observer}: {status}", flush=True)
    finally:
        driver.quit()
    total = a.observers + a.careless
    print(f"{stored} of {total} observers' votes stored in {os.path.join(a.folder, 'votes')}")
    return 0 if stored == total else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
