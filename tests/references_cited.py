#!/usr/bin/env python3
"""Every work cited by author and year is in docs/references.md.

Scans the user- and developer-facing text (include/, src/, tools/, docs/,
README.md, bindings/, examples/, and also CHANGELOG.md, bench/ and tests/
but for their fuzz corpora and data) for citations such as "Thompson (1985)",
"Steger & Sorenson 1979", "Thompson, Thames & Mastin (1974)",
"Brackbill and Saltzman (1982)", "Ly & Norrison's (2007)", "Knupp et al.
1996" or "Steger & Sorenson (1979, 1980)", and fails, naming file and line,
for each one whose first author's surname and year are not together in one
entry of docs/references.md.

The pattern is kept strict so that dates and versions are not citations:
one or more capitalised surnames joined by ",", "&" or "and" (optionally
"et al."), then a year 1900-2029 in parentheses or after a space or comma;
a year followed by "-" and a digit (2026-11-28, 1989-07), by "." and a
digit, or preceded by a digit, "." or "v" is not read. Capitalised words
that are not surnames (month names, "Table", "Debian", ...) are skipped.

    references_cited.py [ROOT]          ROOT: the repository (default: ../)
    references_cited.py --self-test     the check fails on a made-up citation
                                        and passes dates, versions, standards
Standard library only."""
import pathlib
import re
import sys

SCAN = ("include", "src", "tools", "docs", "README.md", "bindings", "examples", "CHANGELOG.md", "bench", "tests")
# Inputs, not text: fuzz corpora and test data; and this file's own made-up citations.
SKIP = (("tests", "fuzz", "corpus"), ("tests", "data"), ("tests", "references_cited.py"))
SUFFIXES = {".md", ".h", ".hpp", ".c", ".cpp", ".py", ".f90", ".toml", ".txt", ".cmake", ".sh", ".in", ""}

NAME = r"(?:[A-Z][a-z\u00e0-\u00ff]+(?:['\u2019](?!s\b)[a-z]+)?(?:-[A-Z][a-z\u00e0-\u00ff]+)?)"
YEAR = r"(?:19|20)\d\d"
CITATION = re.compile(
    rf"(?P<names>{NAME}(?:(?:,\s+|\s+&\s+|\s+and\s+){NAME})*(?:\s+et\s+al\.?)?)"
    rf"(?:'s|\u2019s)?"
    rf"(?:\s+\((?P<pyears>{YEAR}[a-z]?(?:,\s*{YEAR}[a-z]?)*)\)|[ ,]\s*(?P<year>{YEAR})[a-z]?)"
    rf"(?![-./]\d|\d)"
)

# Capitalised words that come before a year without being an author.
NOT_NAMES = {
    "January", "February", "March", "April", "May", "June", "July", "August", "September",
    "October", "November", "December", "Table", "Tables", "Figure", "Fig", "Section", "Version",
    "Release", "Debian", "Ubuntu", "Windows", "Measured", "Re", "Since", "In", "From", "Until",
    "The", "On", "At", "By", "As", "Of", "Published", "Fortran", "Python", "ISO", "C", "CTAC",
    "Vol", "No", "Issue", "Report", "Copyright", "Updated", "Edition", "Press", "Academic",
    "Holland", "North-Holland", "Springer", "Wiley", "Dover", "McGraw-Hill", "CRC", "Phys",
    "Journal", "ANZIAM", "Comput", "Math", "Eindhoven", "Bergen", "Amsterdam",
}


def reference_entries(refs: pathlib.Path):
    """The entries of docs/references.md: its list items, lines joined."""
    entries, current = [], None
    for line in refs.read_text(encoding="utf-8").splitlines():
        if re.match(r"\s*[-*] ", line):
            current = [line]
            entries.append(current)
        elif line.strip() and current is not None and line.startswith(" "):
            current.append(line)
        else:
            current = None
    return [" ".join(e) for e in entries]


def citations(text: str):
    """(line number, first surname, all surnames, years, text) of each citation."""
    for n, line in enumerate(text.splitlines(), 1):
        for m in CITATION.finditer(line):
            names = re.split(r",\s+|\s+&\s+|\s+and\s+", re.sub(r"\s+et\s+al\.?$", "", m.group("names")))
            # Only the run of surnames right before the year: drop leading words
            # that are not surnames ("See Thompson (1985)": "See" is not matched
            # since it is not joined by ",", "&" or "and").
            names = [x for x in names if x not in NOT_NAMES]
            if not names:
                continue
            years = re.findall(YEAR, m.group("pyears") or m.group("year"))
            yield n, names, years, m.group(0)


def files(root: pathlib.Path):
    for top in SCAN:
        base = root / top
        if base.is_file():
            yield base
        elif base.is_dir():
            for f in sorted(base.rglob("*")):
                rel = f.relative_to(root).parts
                if any(rel[:len(p)] == p for p in SKIP):
                    continue
                if f.is_file() and f.suffix in SUFFIXES and "__pycache__" not in f.parts:
                    yield f


def main(root: pathlib.Path) -> int:
    refs = root / "docs" / "references.md"
    entries = reference_entries(refs)
    bad, seen = [], 0
    for f in files(root):
        try:
            text = f.read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue
        if f == refs:
            continue
        for n, names, years, cited in citations(text):
            seen += 1
            first = names[0]
            for year in years:
                if not any(first in e and year in e for e in entries):
                    bad.append(f"{f.relative_to(root)}:{n}: {cited!r}: no entry of docs/references.md "
                               f"names {first} and {year}")
    for b in bad:
        print(b)
    print(f"references_cited: {seen} citations read, {len(bad)} not in docs/references.md")
    return 1 if bad else 0


def self_test() -> int:
    """A scratch tree: one citation missing from its references, and text
    that must not read as citations."""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "docs").mkdir()
        (root / "src").mkdir()
        (root / "docs" / "references.md").write_text(
            "# References\n\n- **Thompson, Thames & Mastin (1974)** — J. F. Thompson et al., 1974.\n"
            "- **Steger & Sorenson (1979, 1980)** — two papers, 1979 and 1980.\n")
        (root / "README.md").write_text(
            "The Poisson system of Thompson, Thames & Mastin (1974) and Steger & Sorenson (1979, 1980).\n"
            "Measured 2026-11-28; eg2d 1.0.0; a Fortran 2003 module; C++17; November 2026.\n")
        (root / "src" / "a.cpp").write_text("// Nobody & Else (1999) is not listed; Thompson's (1985) is not either.\n")
        import io
        import contextlib
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            rc = main(root)
        text = out.getvalue()
        print(text, end="")
        expect = ["src/a.cpp:1: 'Nobody & Else (1999)'", "src/a.cpp:1: \"Thompson's (1985)\"", "2 not in docs/references.md"]
        missing = [e for e in expect if e not in text]
        if rc != 1 or missing:
            print(f"self-test failed: exit {rc}, missing {missing}")
            return 1
        print("self-test: ok")
        return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(main(pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[1]))
