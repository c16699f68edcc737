#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every relative link and image of the README and the user guides (Markdown
links, images and <img src>) names a file or folder of the repository: a guide
that shows a picture nobody committed is broken for its reader."""

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)|<img[^>]*\bsrc=\"([^\"]+)\"")


def targets(md):
    text = md.read_text(encoding="utf-8")
    text = re.sub(r"```.*?```", "", text, flags=re.S)  # code blocks show syntax, not links
    for m in LINK.finditer(text):
        target = m.group(1) or m.group(2)
        if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
            continue  # a URL or an anchor in the same file
        yield target.split("#", 1)[0]


def main():
    pages = [ROOT / "README.md", ROOT / "CHANGES.md"] + sorted((ROOT / "docs").rglob("*.md"))
    missing = [f"{md.relative_to(ROOT)}: {t}" for md in pages if md.exists() for t in targets(md)
               if t and not (md.parent / t).exists()]
    for line in missing:
        print(f"missing: {line}")
    print(f"{len(pages)} pages checked, {len(missing)} links to nothing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
