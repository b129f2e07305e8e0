#!/usr/bin/env python3
"""CTest quickstart_doc (and quality_doc): every command of docs/quickstart.md (or of PAGE), run from the checkout root
with the built CLI, prints exactly the output the page shows (and exits 0); at least MIN commands (default 10).
Usage: quickstart_doc.py CLI SOURCE_DIR [PAGE [MIN]]"""
import os
import shlex
import subprocess
import sys


def blocks(text):
    """The fenced blocks whose first line is "$ wrenchkit ...": (command line, expected output)."""
    out, lines, i = [], text.splitlines(), 0
    while i < len(lines):
        if lines[i].startswith("```") and i + 1 < len(lines) and lines[i + 1].startswith("$ wrenchkit "):
            j = i + 2
            while not lines[j].startswith("```"):
                j += 1
            out.append((lines[i + 1][2:], "\n".join(lines[i + 2:j]) + "\n"))
            i = j
        i += 1
    return out


def main():
    cli, root = sys.argv[1], sys.argv[2]
    page = os.path.join(root, sys.argv[3] if len(sys.argv) > 3 else os.path.join("docs", "quickstart.md"))
    least = int(sys.argv[4]) if len(sys.argv) > 4 else 10
    found = blocks(open(page, encoding="utf-8").read())
    if len(found) < least:
        print(f"quickstart_doc: only {len(found)} commands found in {page}")
        return 1
    bad = 0
    for command, want in found:
        args = shlex.split(command)[1:]
        r = subprocess.run([cli] + args, cwd=root, capture_output=True, text=True)
        if r.returncode != 0 or r.stdout != want:
            bad += 1
            print(f"quickstart_doc: `{command}` exit {r.returncode}\n--- the page shows:\n{want}--- it prints:\n"
                  f"{r.stdout}{r.stderr}")
    print(f"quickstart_doc: {len(found) - bad} of {len(found)} commands print what {page} shows")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
