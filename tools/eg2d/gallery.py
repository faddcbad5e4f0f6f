"""The gallery (docs/gallery.md, docs/gallery/*.svg): every picture is made by the eg2d
command from the example case file it shows, at the file's own size.

    gallery.py EG2D SOURCE_DIR --write   regenerate the pictures and docs/gallery.md
    gallery.py EG2D SOURCE_DIR --check   fail if a committed picture is not what the tool makes now
"""
import difflib
import os
import re
import subprocess
import sys
import tempfile


def examples(src):
    d = os.path.join(src, "examples")
    return sorted(f[:-5] for f in os.listdir(d) if f.endswith(".toml"))


def render(tool, src, name, out):
    """Runs the example; returns the tool's summary (without timings)."""
    case = os.path.join(src, "examples", name + ".toml")
    p = subprocess.run([tool, "run", case, "-o", out, "--quiet"], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"gallery: {name}: eg2d exited {p.returncode}: {p.stderr}")
    lines = [re.sub(r", [0-9.]+ s$", "", l) for l in p.stdout.splitlines() if not l.startswith("wrote ")]
    return lines


def header_comment(src, name):
    text = []
    with open(os.path.join(src, "examples", name + ".toml")) as f:
        for line in f:
            if not line.startswith("#"):
                break
            text.append(line[1:].strip())
    return " ".join(t for t in text if t and not t.startswith("zoom:"))


def zoom_box(src, name):
    """A header line '# zoom: x0 x1 y0 y1' asks for a second picture of that box."""
    with open(os.path.join(src, "examples", name + ".toml")) as f:
        for line in f:
            if not line.startswith("#"):
                break
            m = re.match(r"#\s*zoom:\s*(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", line)
            if m:
                return [float(v) for v in m.groups()]
    return None


def zoomed(svg, box):
    """The same picture with its viewBox on the world box (x0, x1, y0, y1)."""
    m = re.search(r"eg2d frame: xmin (\S+) ymax (\S+) scale (\S+) margin (\S+)", svg)
    xmin, ymax, scale, margin = (float(v) for v in m.groups())
    x0, x1, y0, y1 = box
    px, py = margin + (x0 - xmin) * scale, margin + (ymax - y1) * scale
    w, h = (x1 - x0) * scale, (y1 - y0) * scale
    height = 800.0 * h / w
    # Lines keep their width on the screen: stroke widths scaled down by the zoom.
    svg = re.sub(r"stroke-width:([0-9.]+)", lambda a: f"stroke-width:{float(a.group(1)) * w / 800.0:.4g}", svg)
    return re.sub(r'<svg ([^>]*)width="[^"]*" height="[^"]*" viewBox="[^"]*"',
                  lambda a: f'<svg {a.group(1)}width="800" height="{height:.0f}" viewBox="{px:.3f} {py:.3f} {w:.3f} {h:.3f}"',
                  svg, count=1)


def numbers_close(a, b):
    """Same text apart from numbers, which agree to 0.05 (pixels): tolerant of roundoff."""
    split = re.compile(r"-?\d+\.?\d*(?:e[-+]?\d+)?")
    if split.sub("#", a) != split.sub("#", b):
        return False
    return all(abs(float(x) - float(y)) <= 0.05 for x, y in zip(split.findall(a), split.findall(b)))


def main():
    tool, src, mode = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
    pictures = os.path.join(src, "docs", "gallery")
    if mode == "--check":
        bad = []
        with tempfile.TemporaryDirectory() as out:
            for name in examples(src):
                render(tool, src, name, out)
                committed = os.path.join(pictures, name + ".svg")
                if not os.path.exists(committed):
                    bad.append(f"{name}: docs/gallery/{name}.svg is missing")
                    continue
                with open(committed) as f, open(os.path.join(out, name + ".svg")) as g:
                    made = g.read()
                    if not numbers_close(f.read(), made):
                        bad.append(f"{name}: docs/gallery/{name}.svg differs from what eg2d makes of "
                                   f"examples/{name}.toml")
                box = zoom_box(src, name)
                if box:
                    zpath = os.path.join(pictures, name + "-zoom.svg")
                    if not os.path.exists(zpath) or not numbers_close(open(zpath).read(), zoomed(made, box)):
                        bad.append(f"{name}: docs/gallery/{name}-zoom.svg is missing or stale")
        with open(os.path.join(src, "docs", "gallery.md")) as f:
            md = f.read()
        bad += [f"{n}: not in docs/gallery.md" for n in examples(src) if f"(gallery/{n}.svg)" not in md]
        for b in bad:
            print("gallery:", b)
        if bad:
            print("gallery: regenerate with: cmake --build --preset default --target gallery")
        sys.exit(1 if bad else 0)

    os.makedirs(pictures, exist_ok=True)
    md = ["# Gallery", "",
          "Every picture here is drawn by the `eg2d` command from the case file of",
          "`examples/` named under it, at that file's size (`eg2d run examples/NAME.toml`).",
          "The same files are the built-in demos (`eg2d demo NAME`). Regenerate after a",
          "change: `cmake --build --preset default --target gallery` (ctest's",
          "`gallery_up_to_date` fails while a picture is stale).", ""]
    with tempfile.TemporaryDirectory() as out:
        for name in examples(src):
            summary = render(tool, src, name, out)
            os.replace(os.path.join(out, name + ".svg"), os.path.join(pictures, name + ".svg"))
            md += [f"## {summary[0].split(':')[0]}", "", header_comment(src, name), "",
                   f"Case file: [`examples/{name}.toml`](../examples/{name}.toml) — `eg2d demo {name}`", "",
                   f"![{name}](gallery/{name}.svg)", ""]
            box = zoom_box(src, name)
            if box:
                with open(os.path.join(pictures, name + ".svg")) as f:
                    z = zoomed(f.read(), box)
                with open(os.path.join(pictures, name + "-zoom.svg"), "w") as f:
                    f.write(z)
                md += [f"Near the body, x in [{box[0]:g}, {box[1]:g}], y in [{box[2]:g}, {box[3]:g}]:", "",
                       f"![{name}, near the body](gallery/{name}-zoom.svg)", ""]
            folds = next((l for l in summary if "folded cells" in l), "")
            md += ["```", *summary, "```", ""]
            if folds:
                # a case with solve = false shows its start grid, not a solved one
                what = "the start grid, not solved" if "not solved" in summary[0] else "the converged grid"
                md += [f"What the picture shows: {what}; {folds.split(',')[0].replace('quality: ', '')}.", ""]
    with open(os.path.join(src, "docs", "gallery.md"), "w") as f:
        f.write("\n".join(md))


if __name__ == "__main__":
    main()
