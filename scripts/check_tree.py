#!/usr/bin/python3
"""Checks of the source tree that keep it easy to work in; each fails with file:line messages.

  layers     a file of one engine layer includes only headers of layers it links: the layers and
             their links are read from src/raycast/CMakeLists.txt (`raycast_layer(NAME DEPS ...)`),
             so CMake's link graph is the one definition of what may include what.
  history    no comment, name or page speaks of the project's own development history (its
             sessions, rounds, waves, issue numbers): that story belongs in `git log`.
  functions  no function outside tests is longer than 120 lines (Universal Ctags finds them).

Usage: scripts/check_tree.py CHECK [REPOSITORY]"""
import pathlib
import re
import shutil
import subprocess
import sys

MAX_FUNCTION_LINES = 120
SOURCES = (".h", ".cpp", ".inl", ".py", ".sh", ".txt", ".md", ".html", ".yaml", ".pov", ".in",
           ".cmake", ".pyi", ".ipynb", ".ini", ".toml")
HISTORY_ROOTS = ("src", "apps", "include", "python", "tests", "docs", "bench", "scripts",
                 "examples", "scenes", "cmake", "README.md", "CMakeLists.txt")
HISTORY = re.compile(
    r"\b(?:sessions?|rounds?|waves?)\s+\d+(?:\s*(?:-|,|and)\s*\d+)*\b"
    r"|\bissues?\s*#?\d+"
    r"|\b(?:this|last|next|previous|earlier|later|that|a past|past)\s+(?:sessions?|waves?)\b"
    r"|^#+ .*\bsession\b",
    re.IGNORECASE | re.MULTILINE)


def check_layers(root):
    src = root / "src" / "raycast"
    deps = {}
    cmake = (src / "CMakeLists.txt").read_text()
    for name, body in re.findall(r"raycast_layer\((\w+)\s+DEPS([^)]*)\)", cmake):
        deps[name] = [d[len("raycast_"):] for d in body.split() if d.startswith("raycast_")]

    def below(layer, seen):
        for d in deps.get(layer, []):
            if d not in seen:
                seen.add(d)
                below(d, seen)
        return seen

    include = re.compile(r'^\s*#\s*include\s+"([^"/]+)/[^"]+"', re.M)
    folders = {p.name for p in src.iterdir() if p.is_dir()}
    errors = []
    for layer in sorted(deps):
        allowed = below(layer, set()) | {layer}
        for path in sorted((src / layer).rglob("*")):
            if path.suffix not in (".h", ".cpp", ".inl") or not path.is_file():
                continue
            text = path.read_text()
            for m in include.finditer(text):
                if m.group(1) in folders and m.group(1) not in allowed:
                    line = text.count("\n", 0, m.start()) + 1
                    errors.append(f"{path.relative_to(root)}:{line}: layer '{layer}' includes "
                                  f"'{m.group(1)}/', a layer it does not link (it links: "
                                  f"{', '.join(sorted(allowed - {layer})) or 'nothing'})")
    for folder in sorted(folders - set(deps) - {"plugins"}):
        errors.append(f"src/raycast/{folder}/: a folder that is not a layer in "
                      "src/raycast/CMakeLists.txt")
    return errors, f"{len(deps)} layers, every include points down"


def check_history(root):
    errors = []
    me = pathlib.Path(__file__).resolve()
    files = []
    for name in HISTORY_ROOTS:
        path = root / name
        files += [path] if path.is_file() else sorted(path.rglob("*"))
    for path in files:
        if not path.is_file() or path.suffix not in SOURCES or path.resolve() == me:
            continue
        text = path.read_text(errors="replace")
        for m in HISTORY.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            errors.append(f"{path.relative_to(root)}:{line}: speaks of the project's history "
                          f"('{' '.join(m.group(0).split())}'); say what the code is now, and cite a benchmark "
                          "command for a measurement")
    return errors, f"{len(files)} files speak of the code as it is"


def check_functions(root):
    ctags = shutil.which("ctags")
    if not ctags:
        return ["functions: Universal Ctags is not installed (Debian: universal-ctags)"], ""
    dirs = [str(root / d) for d in ("src", "apps", "include", "python") if (root / d).exists()]
    out = subprocess.run(
        [ctags, "-R", "--languages=C++", "--kinds-C++=f", "--fields=+ne", "--extras=-F", "-x",
         "--_xformat=%{line} %{end} %{input} %{name}"] + dirs,
        capture_output=True, text=True, check=True).stdout
    errors = []
    count = 0
    for row in out.splitlines():
        parts = row.split(" ", 3)
        if len(parts) < 4 or not parts[1].isdigit():
            continue
        count += 1
        lines = int(parts[1]) - int(parts[0]) + 1
        if lines > MAX_FUNCTION_LINES:
            path = pathlib.Path(parts[2]).resolve().relative_to(root.resolve())
            errors.append(f"{path}:{parts[0]}: {parts[3]} is {lines} lines long (at most "
                          f"{MAX_FUNCTION_LINES}): split it into named steps")
    return errors, f"{count} functions, none over {MAX_FUNCTION_LINES} lines"


def main():
    checks = {"layers": check_layers, "history": check_history, "functions": check_functions}
    if len(sys.argv) < 2 or sys.argv[1] not in checks:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else pathlib.Path(__file__).parent.parent)
    errors, summary = checks[sys.argv[1]](root)
    print("\n".join(errors) if errors else f"check_tree {sys.argv[1]}: {summary}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
