#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
"""Runs the commands the documentation shows, as a reader would, so a stale command fails the tests.

Every code block of the given Markdown files is taken: indented blocks and ```sh / ```bash / ```console blocks
are shell commands, run line by line (a line ending in a backslash continues); a ```python block is run with the
documentation's own interpreter (/usr/bin/python3, or the README's virtual environment when a command made one);
a ```cpp block is written to the file its preceding paragraph names in backticks (e.g. `host.cpp`). An HTML
comment right before a block changes what happens to it, and says why:

    <!-- docs-test: skip -- why it cannot run here -->       not run (the reason is printed)
    <!-- docs-test: exists -- why it is not run in full -->  each line's program must exist and be executable
    <!-- docs-test: file NAME -->                             the block is the file NAME, not commands

Commands run in a scratch copy of the repository's tracked files with HOME in the scratch folder and the
repository's build/release tree linked in as build/release (the tree the README's commands use; pass
--build-tree to name another), one bash per file so that a command sees what the ones before it made.

    python3 ci/check_documented_commands.py [--build-tree DIR] [--keep] FILE.md ...

Exit status: 0 every block ran (or was marked), 1 a command failed (the block, its line and its output are
printed), 2 could not start.
"""
import argparse
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
MARK = re.compile(r"^<!--\s*docs-test:\s*(skip|exists|file)\s*(.*?)\s*-->\s*$")
SHELL_LANGUAGES = {"", "sh", "bash", "shell", "console"}


class Block:
    def __init__(self, path, line, kind, text, mark, paragraph):
        self.path, self.line, self.kind, self.text, self.mark, self.paragraph = (path, line, kind, text, mark,
                                                                                 paragraph)

    def where(self):
        return f"{self.path.relative_to(ROOT)}:{self.line}"


def blocks_of(path):
    """The code blocks of a Markdown file, with the docs-test mark before each and the paragraph before it."""
    lines = path.read_text().splitlines()
    blocks, i, paragraph, mark = [], 0, [], None
    while i < len(lines):
        line = lines[i]
        fence = re.match(r"^```\s*([\w+-]*)\s*$", line)
        if fence:
            start, body = i + 1, []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            language = fence.group(1).lower()
            kind = "shell" if language in SHELL_LANGUAGES else language
            blocks.append(Block(path, start, kind, "\n".join(body), mark, " ".join(paragraph)))
            mark, paragraph = None, []
            i += 1
            continue
        previous_blank = i == 0 or not lines[i - 1].strip() or MARK.match(lines[i - 1])
        if line.startswith("    ") and line.strip() and previous_blank and not _in_list(lines, i):
            start, body = i + 1, []
            while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
                body.append(lines[i][4:])
                i += 1
            while body and not body[-1].strip():
                body.pop()
            blocks.append(Block(path, start, "shell", "\n".join(body), mark, " ".join(paragraph)))
            mark, paragraph = None, []
            continue
        m = MARK.match(line)
        if m:
            mark = (m.group(1), m.group(2).lstrip("-— ").strip())
        elif line.strip():
            # The paragraph last written before a block introduces it (a blank line ends it, a new one
            # replaces it).
            paragraph = paragraph + [line] if i > 0 and lines[i - 1].strip() else [line]
        i += 1
    return blocks


def _in_list(lines, i):
    """An indented line continuing a list item is not a code block."""
    j = i - 1
    while j >= 0 and not lines[j].strip():
        j -= 1
    return j >= 0 and re.match(r"^\s*([-*+]|\d+\.)\s", lines[j]) is not None and not lines[j].startswith("    ")


def commands_of(text):
    """Shell lines, with backslash continuations joined and the README's trailing comments kept (bash drops
    them)."""
    commands, current = [], ""
    for raw in text.splitlines():
        line = raw.rstrip()
        if line.endswith("\\"):
            current += line[:-1] + " "
            continue
        current += line
        if current.strip() and not current.strip().startswith("#"):
            commands.append(current.strip())
        current = ""
    return commands


def scratch_copy(scratch, build_tree):
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True).stdout
    for name in filter(None, files.decode().split("\0")):
        source = ROOT / name
        if not source.is_file():
            continue
        target = scratch / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target, follow_symlinks=False)
    (scratch / "build").mkdir(exist_ok=True)
    if build_tree:
        (scratch / "build" / "release").symlink_to(build_tree)
    # What the tree's build made beside the sources and the README's commands read (the generated city).
    generated = ROOT / "scenes" / "generated"
    if generated.is_dir():
        (scratch / "scenes" / "generated").symlink_to(generated)


def run(command, scratch, env, log):
    started = time.monotonic()
    result = subprocess.run(["bash", "-euo", "pipefail", "-c", command], cwd=scratch, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            stdin=subprocess.DEVNULL)
    elapsed = time.monotonic() - started
    log.append((command, result.returncode, elapsed, result.stdout))
    return result.returncode, elapsed, result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", type=pathlib.Path)
    parser.add_argument("--build-tree", type=pathlib.Path, default=ROOT / "build" / "release")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder")
    args = parser.parse_args()
    build_tree = args.build_tree.resolve() if args.build_tree.exists() else None
    if build_tree is None:
        print(f"check_documented_commands: no build tree at {args.build_tree}", file=sys.stderr)
        return 2
    scratch = pathlib.Path(tempfile.mkdtemp(prefix="stipple-docs-"))
    failures, ran, marked = 0, 0, 0
    try:
        scratch_copy(scratch, build_tree)
        (scratch / "home").mkdir()
        for path in args.files:
            path = path.resolve()
            env = {k: v for k, v in os.environ.items() if not k.startswith("STIPPLE_")}
            env["HOME"] = str(scratch / "home")
            # The reader's PATH as it is (another python3 may come first: the README names its interpreter).
            env.pop("PYTHONPATH", None)
            log = []
            for block in blocks_of(path):
                mark = block.mark
                if mark and mark[0] == "skip":
                    marked += 1
                    print(f"skip   {block.where()}: {mark[1]}")
                    continue
                if (mark and mark[0] == "file") or block.kind in ("cpp", "c", "c++"):
                    name = mark[1] if mark and mark[0] == "file" else _named_file(block.paragraph)
                    if not name:
                        print(f"FAIL   {block.where()}: a {block.kind} block that names no file (mark it)")
                        failures += 1
                        continue
                    (scratch / name).write_text(block.text + "\n")
                    print(f"file   {block.where()}: {name}")
                    continue
                if block.kind == "python":
                    python = scratch / ".venv" / "bin" / "python"
                    interpreter = str(python) if python.exists() else "/usr/bin/python3"
                    script = scratch / f"block-{block.line}.py"
                    script.write_text(block.text + "\n")
                    commands = [f"{shlex.quote(interpreter)} {shlex.quote(str(script))}"]
                elif block.kind == "shell":
                    commands = commands_of(block.text)
                else:
                    print(f"pass   {block.where()}: a {block.kind} block (not a command)")
                    continue
                for command in commands:
                    if mark and mark[0] == "exists":
                        program = shlex.split(command, comments=True)[0]
                        ok = os.access(scratch / program, os.X_OK) or shutil.which(program, path=env["PATH"])
                        status = "exists" if ok else "FAIL"
                        print(f"{status:6s} {block.where()}: {program} ({mark[1]})")
                        failures += 0 if ok else 1
                        marked += 1
                        continue
                    code, elapsed, output = run(command, scratch, env, log)
                    ran += 1
                    if code != 0:
                        failures += 1
                        print(f"FAIL   {block.where()}: exit {code} after {elapsed:.1f} s: {command}")
                        print("       " + "\n       ".join(output.strip().splitlines()[-25:]))
                    else:
                        print(f"ok     {block.where()}: {elapsed:6.1f} s  {command[:110]}")
    finally:
        if args.keep:
            print(f"check_documented_commands: scratch kept at {scratch}")
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    print(f"check_documented_commands: {ran} commands ran, {marked} marked, {failures} failed")
    return 1 if failures else 0


def _named_file(paragraph):
    names = re.findall(r"`([\w.-]+\.(?:cpp|cc|c|h|hpp))`", paragraph)
    return names[-1] if names else None


if __name__ == "__main__":
    sys.exit(main())
