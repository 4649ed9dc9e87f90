#!/usr/bin/env python3
"""Writes the file a patch creates (a hunk against /dev/null) as the patch has it, so that the upstream-facing test
that a staging patch adds to a bullet3 checkout is compiled and run by this project's ctest from the patch itself.

  cmake/extract_new_file.py PATCH PATH_IN_PATCH OUT_FILE

Exit 1 with a message naming the patch and the path when the patch does not create that file. OUT_FILE is written
whole (a temporary file renamed) and left untouched when its content is unchanged, so builds do not recompile it.
"""
import os
import sys


def extract(patch, path):
    lines = open(patch, encoding="utf-8").read().split("\n")
    for i, line in enumerate(lines):
        if line == "+++ b/" + path and i > 0 and lines[i - 1] == "--- /dev/null":
            header = lines[i + 1]
            if not header.startswith("@@ -0,0 +1"):
                break
            count = int(header.split("+1,")[1].split(" ")[0]) if "+1," in header else 1
            body = lines[i + 2:i + 2 + count]
            if len(body) != count or not all(b.startswith("+") for b in body):
                raise SystemExit(f"{patch}: the hunk that creates {path} is not {count} added lines")
            return "\n".join(b[1:] for b in body) + "\n"
    raise SystemExit(f"{patch}: does not create {path} (no '--- /dev/null' / '+++ b/{path}' hunk)")


def main(patch, path, out):
    text = extract(patch, path)
    if os.path.exists(out) and open(out, encoding="utf-8").read() == text:
        return
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    tmp = out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, out)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
