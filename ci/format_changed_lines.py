#!/usr/bin/env python3
"""Keeps the hunks of a clang-format-diff report that touch lines a branch changed.

  git diff -U0 BASE HEAD | clang-format-diff -p1 ... > report
  ci/format_changed_lines.py CHANGED.diff < report

clang-format-diff formats the changed line ranges, but it also rewrites the whitespace in front of the
next token after a range: in an upstream file that is not clang-formatted (spaces, trailing blanks) the
line after a changed block is then reported too, though the branch did not touch it. This filter keeps
a hunk only if one of the lines it rewrites is a line the branch added or changed. Prints what is kept.
"""
import re
import sys


def changed_lines(diff_text):
    changed, current, line = {}, None, 0
    for text in diff_text.splitlines():
        if text.startswith("+++ "):
            current = text[4:].split("/", 1)[1] if text[4:].startswith("b/") else text[4:]
            changed.setdefault(current, set())
        elif text.startswith("@@"):
            m = re.match(r"@@ -\d+(?:,\d+)? \+(\d+)(?:,(\d+))? @@", text)
            line = int(m.group(1))
        elif text.startswith("+") and current is not None:
            changed[current].add(line)
            line += 1
        elif text.startswith(" "):
            line += 1
    return changed


def main(changed_diff):
    changed = changed_lines(open(changed_diff).read())
    out, header, hunk, current, keep, line = [], [], [], None, False, 0

    def flush():
        if hunk and keep:
            out.extend(header)
            header.clear()
            out.extend(hunk)

    for text in sys.stdin.read().splitlines():
        if text.startswith("--- "):
            flush()
            hunk, keep = [], False
            path = text[4:].split("\t")[0].strip()
            current = path.split(" ")[0]
            header = [text]
        elif text.startswith("+++ "):
            header.append(text)
        elif text.startswith("@@"):
            flush()
            m = re.match(r"@@ -(\d+)", text)
            line, hunk, keep = int(m.group(1)), [text], False
        elif hunk:
            hunk.append(text)
            if text.startswith("-"):
                if line in changed.get(current, set()):
                    keep = True
                line += 1
            elif text.startswith(" "):
                line += 1
    flush()
    print("\n".join(out))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
