#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
"""No include arrow runs back up inside validation/src.

validation/src is in folders by concern, in layers from the bottom up:

    base < matrix < metrics < run < claims < report = perceptual < (main.cpp)

A file may include a header of its own folder or of a folder below it, spelled from src/ ("run/results.h"),
never one above it. The check fails naming the file, the line, the header and the folders the file may include;
a folder missing from the order, and a validation header spelled any other way, fail too.

    check_include_layers.py [--src DIR]   # default: validation/src of this checkout
    check_include_layers.py --self-test   # the check finds an arrow planted back up, and passes a clean tree
"""

import argparse
import os
import re
import sys
import tempfile

# Rank of each folder: a file may include its own rank or lower. Files at src/ itself (main.cpp) are the top.
LAYERS = {"base": 0, "matrix": 1, "metrics": 2, "run": 3, "claims": 4, "report": 5, "perceptual": 5}
TOP = max(LAYERS.values()) + 1
SOURCE_SUFFIXES = (".h", ".cpp", ".in")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(relative):
    parts = relative.split("/")
    return parts[0] if len(parts) > 1 else ""


def rank_of(folder):
    return TOP if folder == "" else LAYERS.get(folder)


def below(rank):
    return ", ".join(sorted(f for f, r in LAYERS.items() if r <= rank)) or "nothing"


def check(src):
    """The problems found under `src`, one line each."""
    problems = []
    files = []
    for root, _, names in os.walk(src):
        for name in names:
            if name.endswith(SOURCE_SUFFIXES):
                files.append(os.path.relpath(os.path.join(root, name), src).replace(os.sep, "/"))
    known = set(files)
    for relative in sorted(files):
        folder = folder_of(relative)
        rank = rank_of(folder)
        if rank is None:
            problems.append(f"{relative}: folder '{folder}' is not in the layer order of ci/check_include_layers.py")
            continue
        with open(os.path.join(src, relative), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                header = m.group(1)
                if header not in known:
                    # A validation header spelled relative to the including file instead of from src/.
                    beside = os.path.normpath(os.path.join(os.path.dirname(relative), header)).replace(os.sep, "/")
                    if beside in known or os.path.basename(header) in {os.path.basename(k) for k in known}:
                        problems.append(f"{relative}:{number}: \"{header}\": spell a validation header from src/ "
                                        f"(folder/name.h)")
                    continue  # not a validation header (the test vocabulary, a generated file)
                target = rank_of(folder_of(header))
                if target is None or target > rank:
                    where = folder or "src/"
                    problems.append(f"{relative}:{number}: includes {header}, above {where}: {where} may include "
                                    f"only {below(rank)}")
    return problems


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        def write(relative, text):
            path = os.path.join(tmp, relative)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)

        write("base/text.h", "#pragma once\n")
        write("matrix/matrix.h", '#pragma once\n#include "base/text.h"\n')
        write("report/report.h", '#pragma once\n#include "matrix/matrix.h"\n')
        write("main.cpp", '#include "report/report.h"\n')
        clean = check(tmp)
        assert not clean, f"a clean tree was refused: {clean}"
        write("matrix/matrix.cpp", '#include "matrix/matrix.h"\n#include "report/report.h"\n')
        found = check(tmp)
        assert len(found) == 1 and found[0].startswith("matrix/matrix.cpp:2: includes report/report.h"), found
        write("matrix/matrix.cpp", '#include "matrix.h"\n')
        found = check(tmp)
        assert len(found) == 1 and "spell a validation header from src/" in found[0], found
        write("matrix/matrix.cpp", '#include "matrix/matrix.h"\n')
        write("extra/thing.h", "#pragma once\n")
        found = check(tmp)
        assert len(found) == 1 and "folder 'extra' is not in the layer order" in found[0], found
    print("self-test: an arrow back up, a flat spelling and an unknown folder are each found; a clean tree passes")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--src", default=os.path.join(here, "..", "validation", "src"))
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        self_test()
        return 0
    if not os.path.isdir(args.src):
        print(f"check_include_layers: no folder {args.src}", file=sys.stderr)
        return 2
    problems = check(args.src)
    for p in problems:
        print(f"validation/src/{p}", file=sys.stderr)
    if problems:
        print(f"{len(problems)} include(s) against the layers of validation/src", file=sys.stderr)
        return 1
    print("validation/src: every include stays in its layer or below")
    return 0


if __name__ == "__main__":
    sys.exit(main())
