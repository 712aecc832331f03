#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
"""Fails when a package set of ci/install-deps.sh misses a package that its preset's configure needs.

For each set and the preset it serves (main -> main, tests -> release), the preset is configured into a scratch
folder with cmake/DumpImportedFiles.cmake injected, which lists every absolute file the imported targets name
(libraries, executables such as OpenImageIO's tools, include folders). Each file's Debian package (dpkg -S) must
be in the set or among what the set's packages depend on (Depends and Pre-Depends, recursively, as apt installs
them on a fresh machine; recommendations are never installed). A package outside that closure is present here
only because something else installed it, and the set would fail on a freshly installed Debian 12.

    python3 ci/check_package_sets.py [--set SET:PRESET ...] [--expect-missing SET:PACKAGE ...]

--expect-missing checks the checker: with PACKAGE taken out of SET, the check must fail and name it.
Exit status: 0 every set complete (and every expected miss found), 1 a set misses a package, 2 could not check.
"""
import argparse
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
DEFAULT_SETS = ["main:main", "tests:release"]


def set_packages(name):
    out = subprocess.run(["bash", str(ROOT / "ci/install-deps.sh"), "--list", name], check=True,
                         capture_output=True, text=True).stdout
    return set(out.split())


def installed_packages():
    """name -> (alternatives lists of Depends + Pre-Depends), and virtual name -> providers, for installed ones."""
    fmt = "${Package}\t${db:Status-Abbrev}\t${Depends}\t${Pre-Depends}\t${Provides}\n"
    out = subprocess.run(["dpkg-query", "-W", "-f", fmt], check=True, capture_output=True, text=True).stdout
    depends, providers = {}, {}
    for line in out.splitlines():
        package, status, dep, predep, provides = (line.split("\t") + [""] * 5)[:5]
        if not status.startswith("ii"):
            continue
        groups = []
        for field in (dep, predep):
            for group in filter(None, (g.strip() for g in field.split(","))):
                groups.append([re.split(r"[ (:]", alt.strip())[0] for alt in group.split("|")])
        depends[package] = groups
        for virtual in filter(None, (p.strip() for p in provides.split(","))):
            providers.setdefault(re.split(r"[ (:]", virtual)[0], []).append(package)
    return depends, providers


def closure(roots, depends, providers):
    """What apt installs for roots: each dependency group satisfied by its first installed alternative."""
    seen, stack = set(), list(roots)
    while stack:
        package = stack.pop()
        if package in seen:
            continue
        seen.add(package)
        for group in depends.get(package, []):
            if any(alt in seen for alt in group):
                continue
            for alt in group:
                if alt in depends:
                    stack.append(alt)
                    break
                if alt in providers:
                    stack.append(providers[alt][0])
                    break
    return seen


def imported_files(preset, scratch):
    build = scratch / preset
    out = scratch / f"{preset}.files"
    result = subprocess.run(["cmake", "--preset", preset, "-B", str(build),
                             f"-DCMAKE_PROJECT_INCLUDE={ROOT / 'cmake/DumpImportedFiles.cmake'}",
                             f"-DSTIPPLE_IMPORTED_FILES_OUT={out}"],
                            cwd=ROOT, capture_output=True, text=True)
    if result.returncode != 0 or not out.exists():
        sys.stderr.write(result.stdout[-3000:] + result.stderr[-3000:])
        raise SystemExit(f"check_package_sets: configuring preset {preset} failed (output above)")
    pairs = []
    for line in out.read_text().splitlines():
        if "\t" in line:
            target, path = line.split("\t", 1)
            pairs.append((target, path))
    return pairs


def owners(paths):
    """path -> set of Debian packages owning it (merged /usr: the /lib spelling is tried too)."""
    result = {}
    for path in paths:
        candidates = [path]
        resolved = str(pathlib.Path(path).resolve())
        candidates.append(resolved)
        for c in list(candidates):
            if c.startswith("/usr/lib/"):
                candidates.append(c[len("/usr"):])
        found = set()
        for c in dict.fromkeys(candidates):
            q = subprocess.run(["dpkg-query", "-S", c], capture_output=True, text=True)
            for line in q.stdout.splitlines():
                names, _, owned = line.rpartition(": ")
                if owned == c:
                    found.update(n.strip().split(":")[0] for n in names.split(","))
        result[path] = found
    return result


def missing_for(set_name, packages, pairs, owner_of, depends, providers):
    installed = closure(packages, depends, providers)
    problems = []
    for target, path in pairs:
        if path.startswith(str(ROOT)):
            continue
        if not pathlib.Path(path).exists():
            continue  # the project's CMake copes with it (e.g. OIIO's opencv4 folder), or configure fails anyway
        found = owner_of[path]
        if found and not (found & installed):
            problems.append((target, path, sorted(found)))
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--set", action="append", dest="sets", metavar="SET:PRESET")
    parser.add_argument("--expect-missing", action="append", default=[], metavar="SET:PACKAGE")
    args = parser.parse_args()
    sets = [s.split(":", 1) for s in (args.sets or DEFAULT_SETS)]
    depends, providers = installed_packages()
    status = 0
    with tempfile.TemporaryDirectory(prefix="stipple-package-sets-") as scratch:
        scratch = pathlib.Path(scratch)
        for set_name, preset in sets:
            packages = set_packages(set_name)
            pairs = imported_files(preset, scratch)
            owner_of = owners(sorted({p for _, p in pairs if not p.startswith(str(ROOT))}))
            problems = missing_for(set_name, packages, pairs, owner_of, depends, providers)
            for target, path, found in problems:
                status = 1
                print(f"check_package_sets: set '{set_name}' (preset {preset}) misses {' or '.join(found)}: "
                      f"{target} names {path}")
            if not problems:
                print(f"check_package_sets: set '{set_name}' (preset {preset}) installs every one of the "
                      f"{len(owner_of)} files its imported targets name")
            for expectation in args.expect_missing:
                expected_set, dropped = expectation.split(":", 1)
                if expected_set != set_name:
                    continue
                if dropped not in packages:
                    print(f"check_package_sets: --expect-missing {expectation}: {dropped} is not in set "
                          f"'{set_name}'")
                    status = status or 2
                    continue
                found = missing_for(set_name, packages - {dropped}, pairs, owner_of, depends, providers)
                if any(f and dropped in f for _, _, f in found):
                    print(f"check_package_sets: without {dropped}, set '{set_name}' is reported incomplete, "
                          "as it must be")
                else:
                    print(f"check_package_sets: without {dropped}, set '{set_name}' was NOT reported incomplete")
                    status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
