#!/usr/bin/env python3
"""Runs the example commands of docs/cli.md as written (CTest `docs_cli_examples`, label `docs`).

  run_cli_examples.py EXACTVIS_BINARY SOURCE_DIR [--list]

Every backquoted command starting with `exactvis ` on a line with `Example:` (or `Example (...):`) is run,
in the order of the page, in one temporary directory holding a copy of SOURCE_DIR/scenes; it must exit 0
and leave every output it names (-o/--output, --vtp, --svg, --png, --ply: a file or a directory). A line
`Error example: `CMD` fails with `MESSAGE`` runs CMD, which must exit 1 with MESSAGE as the last line of
stderr, and leave no output it names. Every `## subcommand` section must have at least one example.
The first word `exactvis` is replaced by EXACTVIS_BINARY; the rest is split like a POSIX shell would
(shlex), without running a shell.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

OUTPUT_OPTIONS = ("-o", "--output", "--vtp", "--svg", "--png", "--ply")
TIMEOUT = 120  # seconds per command: a hang fails the test instead of blocking CI


def examples(markdown):
    """[(line number, section, kind, command, expected message or None)] in page order."""
    out = []
    section = None
    for number, line in enumerate(markdown.splitlines(), 1):
        m = re.match(r"## (\S+)", line)
        if m:
            section = m.group(1)
            continue
        if re.match(r"\s*Error example:", line):
            m = re.match(r"\s*Error example: `(exactvis [^`]*)` fails with `([^`]*)`", line)
            if not m:
                raise SystemExit(f"docs/cli.md:{number}: an Error example must read "
                                 "'Error example: `exactvis ...` fails with `MESSAGE`'")
            out.append((number, section, "error", m.group(1), m.group(2)))
        elif re.search(r"\bExamples?( \([^)]*\))?:", line):
            tail = line[re.search(r"\bExamples?( \([^)]*\))?:", line).end():]
            for cmd in re.findall(r"`(exactvis [^`]*)`", tail):
                out.append((number, section, "ok", cmd, None))
    return out


def outputs(argv):
    named = []
    for k, a in enumerate(argv):
        if a in OUTPUT_OPTIONS and k + 1 < len(argv):
            named.append(argv[k + 1])
        for opt in OUTPUT_OPTIONS:
            if opt.startswith("--") and a.startswith(opt + "="):
                named.append(a[len(opt) + 1:])
    return named


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    binary, source = os.path.abspath(sys.argv[1]), sys.argv[2]
    with open(os.path.join(source, "docs", "cli.md"), encoding="utf-8") as f:
        page = f.read()
    found = examples(page)
    if "--list" in sys.argv:
        for number, section, kind, cmd, msg in found:
            print(f"{number}: [{section}] {kind}: {cmd}" + (f"  ->  {msg}" if msg else ""))
        return 0
    sections = [m.group(1) for m in re.finditer(r"^## (\S+)", page, re.M)]
    failures = [f"section '{s}' has no example" for s in sections if not any(e[1] == s for e in found)]
    with tempfile.TemporaryDirectory(prefix="exactvis-docs-") as work:
        shutil.copytree(os.path.join(source, "scenes"), os.path.join(work, "scenes"))
        for number, section, kind, cmd, msg in found:
            argv = shlex.split(cmd)
            argv[0] = binary
            where = f"docs/cli.md:{number}: `{cmd}`"
            try:
                r = subprocess.run(argv, cwd=work, capture_output=True, text=True, timeout=TIMEOUT,
                                   stdin=subprocess.DEVNULL)
            except subprocess.TimeoutExpired:
                failures.append(f"{where}: no answer after {TIMEOUT} s")
                continue
            last = (r.stderr.strip().splitlines() or [""])[-1]
            if kind == "ok":
                if r.returncode != 0:
                    failures.append(f"{where}: exit status {r.returncode}: {last}")
                    continue
                for path in outputs(argv):
                    if not os.path.exists(os.path.join(work, path)):
                        failures.append(f"{where}: the output {path} was not written")
            else:
                if r.returncode != 1:
                    failures.append(f"{where}: exit status {r.returncode}, expected 1")
                elif last != msg:
                    failures.append(f"{where}: the message is\n    {last}\n  not the documented\n    {msg}")
                for path in outputs(argv):
                    if os.path.exists(os.path.join(work, path)):
                        failures.append(f"{where}: failed but left the output {path}")
            print(f"{'ok  ' if kind == 'ok' else 'err '} {cmd}")
    for f in failures:
        print("FAIL " + f, file=sys.stderr)
    print(f"{len(found)} examples of docs/cli.md, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
