#!/usr/bin/env python3
"""Fails when a relative link of README.md or docs/*.md, or a repository path
named in include/eg2d.h or examples/*.toml comments, does not resolve, or
when user-facing text (README, docs, include, tools, examples) uses an
internal label ("seed 003", "issue 5") instead of an author and year.

Markdown: every [text](target) whose target is not a URL or an #anchor must
name an existing file or directory, relative to the page. The header and case
files: every path like docs/NUMERICS.md or bench/RESULTS.md they mention must
exist from the repository root."""
import pathlib
import re
import sys

LINK = re.compile(r"\]\(([^)\s]+)\)")
PATH = re.compile(r"\b((?:docs|bench|examples|tests|tools|include|src|bindings|abi)/[\w./-]*\w)")


def main(root: pathlib.Path) -> int:
    bad, checked = [], 0
    pages = [root / "README.md", *sorted((root / "docs").rglob("*.md"))]
    for page in pages:
        for m in LINK.finditer(page.read_text()):
            target = m.group(1).split("#")[0]
            if not target or re.match(r"^[a-z]+:", target):
                continue
            checked += 1
            if not (page.parent / target).exists():
                bad.append(f"{page.relative_to(root)}: link to {m.group(1)} does not resolve")
    for text_file in [root / "include" / "eg2d.h", *sorted((root / "examples").glob("*.toml"))]:
        for m in PATH.finditer(text_file.read_text()):
            checked += 1
            if not (root / m.group(1)).exists():
                bad.append(f"{text_file.relative_to(root)}: names {m.group(1)}, which does not exist")
    # No internal labels in user-facing text: papers by author and year.
    label = re.compile(r"seed 0|issue [0-9]", re.I)
    for top in ("README.md", "docs", "include", "tools", "examples"):
        base = root / top
        for f in [base] if base.is_file() else sorted(p for p in base.rglob("*") if p.is_file()):
            if f.suffix not in (".md", ".h", ".hpp", ".toml", ".cpp", ".py", ".c", ".f90", ".svg") or "checks" in f.parts:
                continue
            for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
                checked += 1
                if label.search(line):
                    bad.append(f"{f.relative_to(root)}:{n}: an internal label: {line.strip()[:80]}")
    for b in bad:
        print(b)
    print(f"links: {checked} checked, {len(bad)} broken")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]))
