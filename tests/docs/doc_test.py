#!/usr/bin/env python3
"""Doc-test: runs every command that README.md and docs/user-guide.md show, so that they stay true.

Usage: tests/docs/doc_test.py PATH/TO/locus SOURCE_DIR [DOC.md ...] [--list] [--timeout S]
(ctest runs it as `docs.commands`; the documents default to README.md and docs/user-guide.md).
Python 3 standard library only.

What counts as a command (the extraction rule)
----------------------------------------------
Only fenced code blocks (``` ... ```) are read; prose and inline code are not.

* A line of a fenced block that starts with `$ ` is a shell command, typed as a reader would
  type it: `$ locus groebner f.ideal --stats`, `$ printf '...' | locus groebner -`,
  `$ locus ... | head -3`, `$ cat FILE`. A line ending in `\\` continues on the next line.
  Every non-`$` line after it, up to the next `$` line or the end of the block, is its shown
  output (standard output and standard error together, as a terminal shows them). A command
  with no lines after it shows no output, and its output is then not compared.
* In a block with no `$` line, a line that starts with `locus ` (not `locus:`, which is an
  error message) is a synopsis, such as `locus groebner FILE [--order O] ...`, continued by
  the indented lines after it. A synopsis is not run; it is checked against the tool: its
  subcommand must exist, and every option it names (`--order`, `-o`) must appear in
  `locus SUBCOMMAND --help`.
* Other blocks (file contents, sample output without a command, make targets) are not tested.

How a command runs
------------------
The source tree is mirrored once into a temporary directory as a tree of symbolic links (`cp -rs`
of every top-level entry except `build` and hidden ones). Each fenced block is a session of its
own: it runs in a fresh temporary directory holding links to the mirror's top-level entries, so
the repository's paths (`tests/data/known/...`, `bench/data/...`, `docs/scenes/...`) resolve as
from the source root, while every file a command writes (`-o whitney.png`, or even
`-o docs/x.png`) lands in temporary directories, never in the source tree. The files of
tests/docs/fixtures/ (the small ideals that the docs describe only in prose, such as `A.ideal`)
are copied into it too. `locus` on the PATH is the binary under test. Commands run with
`bash -c` (the status of a pipeline is that of its last command, as in an interactive shell),
each under `timeout` (--timeout, default 30 s per command).

* A `$` command must run `locus` (at its start or after `|`, `;`, `&`, `(`), or be `cat FILE`;
  anything else (`$ make test`) fails the test unless its block is marked `skip`.
* `$ cat NAME`, where NAME is a plain file name (no `/`) that does not exist, defines NAME: it
  is written with the shown lines, so that a doc can show a small input file and then use it.
  Otherwise (an existing file, or any path with a `/`, which must then exist in the repository)
  the command runs like any other and the file's content must match.
* Exit code: 0, unless the command ends in `; echo $?`, in which case the last shown line is the
  expected code (and the rest is the shown output), or a marker before the block says otherwise.
* Output: the shown lines must be exactly the actual lines of standard output and standard
  error, interleaved in any way that keeps the order within each stream (the two streams are
  captured apart, so their relative order is not reproducible). Trailing spaces are ignored.
  Times are masked on both sides: a number followed by ` s`, ` ms` or ` M primary rays/s`.

Markers: an HTML comment right before a fenced block (blank lines allowed between) changes how
the whole block is tested; GitHub does not display it:

    <!-- doc-test: skip (REASON) -->          not run; listed with REASON at the end
    <!-- doc-test: exit N -->                  every command of the block must exit with N
                                               (unless it ends in `; echo $?`)
    <!-- doc-test: numbers vary (REASON) -->   compare the output with every number masked
                                               (counts that depend on the machine's speed)

Several markers may precede one block. Skips must be few and each must give a reason; the
script prints them all.
"""

import argparse
import difflib
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

DEFAULT_DOCS = ["README.md", "docs/user-guide.md"]
FENCE = re.compile(r"^\s*(```|~~~)")
MARKER = re.compile(r"^\s*<!--\s*doc-test:\s*(.*?)\s*-->\s*$")
ECHO_STATUS = re.compile(r";\s*echo\s+\$\?\s*$")
TIME = re.compile(r"\d+(?:\.\d+)?(?= s\b| ms\b| M primary rays/s)")
NUMBER = re.compile(r"\d+(?:\.\d+)?")
LOCUS_WORD = re.compile(r"(^|[|;&(]\s*)locus(\s|$)")
OPTION = re.compile(r"(?<![\w-])(--?[A-Za-z][\w-]*)")


class Block:
    def __init__(self, doc, line, markers):
        self.doc, self.line, self.markers = doc, line, markers
        self.lines = []  # (line number, text)


class Command:
    def __init__(self, doc, line, text):
        self.doc, self.line, self.text = doc, line, text
        self.shown = []

    def where(self):
        return f"{self.doc}:{self.line}"


def read_blocks(path, doc):
    """The fenced blocks of a Markdown file, each with the doc-test markers right before it."""
    blocks, markers, block = [], [], None
    with open(path, encoding="utf-8") as f:
        for number, raw in enumerate(f, 1):
            text = raw.rstrip("\n")
            if block is not None:
                if FENCE.match(text):
                    blocks.append(block)
                    block = None
                else:
                    block.lines.append((number, text))
                continue
            if FENCE.match(text):
                block = Block(doc, number, markers)
                markers = []
                continue
            marker = MARKER.match(text)
            if marker:
                markers.append((number, marker.group(1)))
            elif text.strip():
                if markers:
                    sys.exit(f"{doc}:{markers[0][0]}: a doc-test marker must come right before a "
                             "fenced code block")
    if block is not None:
        sys.exit(f"{doc}:{block.line}: unclosed code block")
    if markers:
        sys.exit(f"{doc}:{markers[0][0]}: a doc-test marker must come right before a "
                 "fenced code block")
    return blocks


def parse_markers(block):
    settings = {"skip": None, "exit": None, "numbers": False}
    for number, text in block.markers:
        if m := re.fullmatch(r"skip\s*\((.+)\)", text):
            settings["skip"] = m.group(1)
        elif m := re.fullmatch(r"exit\s+(\d+)", text):
            settings["exit"] = int(m.group(1))
        elif re.fullmatch(r"numbers vary\s*\((.+)\)", text):
            settings["numbers"] = True
        else:
            sys.exit(f"{block.doc}:{number}: unknown doc-test marker '{text}' (skip (REASON), "
                     "exit N, numbers vary (REASON))")
    return settings


def commands_of(block):
    """The `$` commands of a block with their shown output, and its synopsis lines."""
    commands, synopses = [], []
    has_prompt = any(text.startswith("$ ") for _, text in block.lines)
    if not has_prompt:
        last = None  # the line number of the synopsis line just read
        for number, text in block.lines:
            if text.startswith("locus ") or text == "locus":
                synopses.append(Command(block.doc, number, text))
                last = number
            elif last is not None and last + 1 == number and text[:1].isspace():
                synopses[-1].text += " " + text.strip()
                last = number
        return commands, synopses
    continuing = None
    for number, text in block.lines:
        if continuing is not None:
            continuing.text += "\n" + text
            if not text.endswith("\\"):
                continuing = None
            continue
        if text.startswith("$ "):
            commands.append(Command(block.doc, number, text[2:]))
            if text.endswith("\\"):
                continuing = commands[-1]
        elif commands:
            commands[-1].shown.append(text.rstrip())
        else:
            sys.exit(f"{block.doc}:{number}: output before the first `$` command of the block")
    return commands, synopses


def interleaves(shown, out, err):
    """Whether `shown` is `out` and `err` merged, keeping the order within each."""
    if len(shown) != len(out) + len(err):
        return False
    reach = [[False] * (len(err) + 1) for _ in range(len(out) + 1)]
    reach[0][0] = True
    for i in range(len(out) + 1):
        for j in range(len(err) + 1):
            if not reach[i][j]:
                continue
            k = i + j
            if k == len(shown):
                continue
            if i < len(out) and out[i] == shown[k]:
                reach[i + 1][j] = True
            if j < len(err) and err[j] == shown[k]:
                reach[i][j + 1] = True
    return reach[len(out)][len(err)]


def mirror(source, target):
    """A tree of symbolic links to the source tree's files (build/ and hidden entries left out)."""
    os.makedirs(target)
    entries = [os.path.join(source, e) for e in sorted(os.listdir(source))
               if e != "build" and not e.startswith(".")]
    subprocess.run(["cp", "-rs"] + entries + [target], check=True)


def session(tree, target, fixtures):
    """A fresh working directory: links to the mirror's top-level entries, and the fixtures."""
    os.makedirs(target)
    for entry in os.listdir(tree):
        os.symlink(os.path.join(tree, entry), os.path.join(target, entry))
    for name in os.listdir(fixtures) if os.path.isdir(fixtures) else []:
        shutil.copy(os.path.join(fixtures, name), target)


def check_synopsis(synopsis, locus, helps):
    words = synopsis.text.split()
    sub = words[1] if len(words) > 1 and not words[1].startswith("-") else ""
    if sub not in helps:
        result = subprocess.run([locus] + ([sub] if sub else []) + ["--help"],
                                capture_output=True, text=True, timeout=30)
        helps[sub] = result.stdout if result.returncode == 0 else None
    help_text = helps[sub]
    if help_text is None:
        return [f"`locus {sub} --help` fails: no such subcommand"]
    missing = []
    for option in OPTION.findall(" ".join(words[2 if sub else 1:])):
        if not re.search(r"(?<![\w-])" + re.escape(option) + r"(?![\w-])", help_text):
            missing.append(f"option {option} is not in `locus {sub} --help`")
    return missing


def run_command(command, settings, workdir, env, limit):
    """Runs one `$` command; returns a list of problems (empty when it agrees with the doc)."""
    text, shown = command.text, list(command.shown)
    expected = settings["exit"] if settings["exit"] is not None else 0
    if ECHO_STATUS.search(text):
        text = ECHO_STATUS.sub("", text)
        if not shown or not shown[-1].strip().isdigit():
            return ["ends in `; echo $?` but the last shown line is not an exit code"]
        expected = int(shown.pop().strip())
    cat = re.fullmatch(r"cat\s+([\w.-]+)", text.strip())
    if not cat and not re.fullmatch(r"cat\s+\S+", text.strip()) and not LOCUS_WORD.search(text):
        return ["neither runs locus nor is `cat FILE`: mark the block `<!-- doc-test: skip "
                "(REASON) -->` if it must not run"]
    if cat and not os.path.exists(os.path.join(workdir, cat.group(1))):
        with open(os.path.join(workdir, cat.group(1)), "w", encoding="utf-8") as f:
            f.write("".join(line + "\n" for line in shown))
        return None  # a file definition, not a command
    try:
        result = subprocess.run(["timeout", "-k", "5", str(limit), "bash", "-c", text],
                                cwd=workdir, env=env, capture_output=True, timeout=limit + 30)
    except subprocess.TimeoutExpired:
        return [f"did not end within {limit + 30} s"]
    out = result.stdout.decode("utf-8", "replace").splitlines()
    err = result.stderr.decode("utf-8", "replace").splitlines()
    problems = []
    if result.returncode == 124:
        problems.append(f"timed out after {limit} s (timeout)")
    elif result.returncode != expected:
        hint = ""
        if expected == 0 and any(line.startswith("locus: ") for line in shown):
            hint = (" (the doc shows an error: end the command in `; echo $?` or put "
                    "`<!-- doc-test: exit N -->` before the block)")
        problems.append(f"exit {result.returncode}, expected {expected}{hint}")
    if shown:
        def mask(lines):
            lines = [TIME.sub("<time>", line.rstrip()) for line in lines]
            if settings["numbers"]:
                lines = [NUMBER.sub("<n>", line) for line in lines]
            return lines
        if not interleaves(mask(shown), mask(out), mask(err)):
            diff = difflib.unified_diff(shown, out + err, "shown in the doc",
                                        "actual (stdout, then stderr)", lineterm="", n=1)
            problems.append("the output differs:\n" + "\n".join("      " + l for l in diff))
    if problems and not shown:
        problems.append("actual output:\n" + "\n".join("      " + l for l in (out + err)[:8]))
    return problems


def report(problems, item, text, ok_text):
    """Prints one check's line (and its problems); returns 1 for a failure, else 0."""
    if problems:
        print(f"FAIL {item.where()}: {text}")
        for p in problems:
            print("     " + p)
        return 1
    print(f"ok   {item.where()}: {ok_text}")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("locus")
    parser.add_argument("source")
    parser.add_argument("docs", nargs="*", default=DEFAULT_DOCS)
    parser.add_argument("--timeout", type=float, default=30, help="seconds per command")
    parser.add_argument("--list", action="store_true", help="list the commands, run nothing")
    args = parser.parse_args()
    locus = os.path.abspath(args.locus)
    source = os.path.abspath(args.source)
    fixtures = os.path.join(source, "tests", "docs", "fixtures")

    started = time.monotonic()
    tmp = tempfile.mkdtemp(prefix="locus-doc-test-")
    os.makedirs(os.path.join(tmp, "bin"))
    os.symlink(locus, os.path.join(tmp, "bin", "locus"))
    env = dict(os.environ, PATH=os.path.join(tmp, "bin") + os.pathsep + os.environ["PATH"])
    env.pop("CI", None)
    tree = os.path.join(tmp, "source")

    failures, ran, defined, checked, skipped, helps = 0, 0, 0, 0, [], {}
    try:
        for doc in args.docs:
            for block in read_blocks(os.path.join(source, doc), doc):
                settings = parse_markers(block)
                commands, synopses = commands_of(block)
                if settings["skip"] is not None:
                    skipped += [(f"{c.where()}: $ {c.text}", settings["skip"]) for c in commands]
                    skipped += [(f"{c.where()}: {c.text}", settings["skip"]) for c in synopses]
                    continue
                if args.list:
                    for c in synopses:
                        print(f"synopsis {c.where()}: {c.text}")
                    for c in commands:
                        print(f"command  {c.where()}: {c.text}")
                    continue
                for synopsis in synopses:
                    problems = check_synopsis(synopsis, locus, helps)
                    checked += 1
                    failures += report(problems, synopsis, synopsis.text,
                                       f"(synopsis) {synopsis.text[:70]}")
                if not commands:
                    continue
                if not os.path.isdir(tree):
                    mirror(source, tree)
                workdir = os.path.join(tmp, f"{os.path.basename(doc)}.{block.line}")
                session(tree, workdir, fixtures)
                for command in commands:
                    before = time.monotonic()
                    problems = run_command(command, settings, workdir, env, args.timeout)
                    took = time.monotonic() - before
                    if problems is None:
                        defined += 1
                        print(f"file {command.where()}: {command.text}")
                        continue
                    ran += 1
                    failures += report(problems, command, f"$ {command.text}",
                                       f"$ {command.text[:80]} ({took:.1f} s)")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)

    for what, reason in skipped:
        print(f"skip {what}  -- {reason}")
    print(f"{ran} commands run, {checked} synopses checked, {defined} files defined by `cat`, "
          f"{len(skipped)} skipped; {failures} failed ({time.monotonic() - started:.1f} s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
