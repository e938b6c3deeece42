#!/usr/bin/python3
"""Checks the user documentation: every command it shows runs, every relative link resolves.

Pages checked: README.md, CHANGELOG.md and docs/*.md.

Commands: each fenced ```sh block is run with `bash -e`. A page's blocks run in order in one fresh
scratch folder per page (so a tutorial's steps build on each other). The folder holds symlinks
`scenes`, `examples`, `python` and `tests` to the repository's folders and `build/release` to the
release build folder; `build/release` is first on PATH (so `raycast ...` and `build/release/raycast ...`
both work), followed by /usr/local/bin, /usr/bin and /bin (so `python3` is Debian's, for which the
module is built), and PYTHONPATH is `build/release/python`. A block whose preceding line is
`<!-- not run: REASON -->` is skipped; REASON must say why (set-up, a long benchmark, a peer that
CI does not install). Each block has BLOCK_TIMEOUT_S seconds: commands in the docs must be quick.

Links: every Markdown link or image whose target is not a URL must name an existing file or
folder, relative to the page; an `#anchor` into a Markdown page (or the page itself) must be one
of its headings, spelt as GitHub spells heading anchors. The index, docs/README.md, must link every
page of docs/.

Exit code 0 when everything passes, 1 when something fails (each failure names the page, the
line and what went wrong), 2 on bad usage.
"""

import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*([\w+-]*)")
NOT_RUN = re.compile(r"^\s*<!--\s*not run:(.*?)-->\s*$")
# [text](target) and ![alt](target); the target ends at whitespace or the closing parenthesis.
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
INLINE_CODE = re.compile(r"`+[^`]*`+")
# The repository folders a command in the docs may name, relative to its scratch folder.
LINKED_FOLDERS = ("scenes", "examples", "python", "tests")
BLOCK_TIMEOUT_S = 120


class Block:
    """One fenced ```sh block: its page, the line of its opening fence, its text, and whether to
    run it (with the reason when not)."""

    def __init__(self, page, line, text, skip_reason):
        self.page, self.line, self.text, self.skip_reason = page, line, text, skip_reason


def pages(root):
    """The Markdown pages the check covers, as paths relative to root, in a stable order."""
    found = [n for n in ("README.md", "CHANGELOG.md") if os.path.isfile(os.path.join(root, n))]
    docs = os.path.join(root, "docs")
    if os.path.isdir(docs):
        found += sorted("docs/" + n for n in os.listdir(docs) if n.endswith(".md"))
    return found


def scan(root, page):
    """Returns (blocks, problems) for one page: its ```sh blocks and the problems found while
    reading it (a skip marker without a reason, an unclosed fence, a broken link)."""
    blocks, problems = [], []
    with open(os.path.join(root, page), encoding="utf-8") as f:
        lines = f.read().split("\n")
    fence = None  # (marker, language, first line number, body lines, skip reason)
    previous = ""
    for number, line in enumerate(lines, start=1):
        if fence is not None:
            marker, language, start, body, reason = fence
            if line.strip().startswith(marker) and line.strip().strip(marker[0]) == "":
                if language == "sh":
                    blocks.append(Block(page, start, "\n".join(body) + "\n", reason))
                fence = None
            else:
                body.append(line)
            continue
        opening = FENCE.match(line)
        if opening:
            reason = None
            marked = NOT_RUN.match(previous)
            if marked:
                reason = marked.group(1).strip()
                if not reason:
                    problems.append(f"{page}:{number - 1}: `<!-- not run: -->` needs a reason")
                    reason = "(no reason given)"
            fence = (opening.group(2), opening.group(3), number, [], reason)
        else:
            problems += broken_links(root, page, number, line)
        if line.strip():
            previous = line
    if fence is not None:
        problems.append(f"{page}:{fence[2]}: code fence never closed")
    return blocks, problems


def heading_anchor(heading):
    """GitHub's anchor of a heading: lower case, punctuation other than '-' and '_' dropped, each
    space a hyphen."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(root, page):
    """The anchors of a Markdown page's headings (outside code fences)."""
    found, fenced = set(), False
    with open(os.path.join(root, page), encoding="utf-8") as f:
        for line in f:
            if FENCE.match(line):
                fenced = not fenced
            elif not fenced and re.match(r"^#{1,6} ", line):
                found.add(heading_anchor(line.lstrip("#")))
    return found


def broken_links(root, page, number, line):
    """The problems with the relative links on one line of prose (inline code is not prose)."""
    problems = []
    for match in LINK.finditer(INLINE_CODE.sub("", line)):
        target = match.group(1)
        if re.match(r"^[a-z][a-z0-9+.-]*:", target):
            continue
        path, _, anchor = target.partition("#")
        linked = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
        if not os.path.exists(os.path.join(root, linked)):
            problems.append(f"{page}:{number}: link to a missing file: {target}")
        elif anchor and linked.endswith(".md") and anchor not in anchors(root, linked):
            problems.append(f"{page}:{number}: link to a missing heading: {target}")
    return problems


def unindexed_pages(root):
    """The problems of the index docs/README.md: each page of docs/ that it does not link."""
    index = os.path.join(root, "docs", "README.md")
    if not os.path.isfile(index):
        return []
    with open(index, encoding="utf-8") as f:
        linked = {os.path.normpath(m.group(1).partition("#")[0]) for m in LINK.finditer(f.read())}
    return [f"docs/README.md: the index does not link docs/{name}"
            for name in sorted(os.listdir(os.path.join(root, "docs")))
            if name.endswith(".md") and name != "README.md" and name not in linked]


def make_scratch(root, build_dir):
    """A fresh folder holding the symlinks a documented command may use."""
    scratch = tempfile.mkdtemp(prefix="raycast-docs-")
    for name in LINKED_FOLDERS:
        os.symlink(os.path.join(root, name), os.path.join(scratch, name))
    os.mkdir(os.path.join(scratch, "build"))
    os.symlink(build_dir, os.path.join(scratch, "build", "release"))
    return scratch


def run_page(blocks, root, build_dir):
    """Runs one page's blocks in order in one scratch folder; returns the report of the first
    block that fails (naming the page and the line), or None when all pass. Later blocks are not
    run after a failure: they may build on it."""
    scratch = make_scratch(root, build_dir)
    try:
        env = dict(os.environ)
        release = os.path.join(scratch, "build", "release")
        # A Debian user's PATH: the build first, then the system's interpreters (the Python
        # module is built for /usr/bin/python3), then whatever else this environment adds.
        env["PATH"] = os.pathsep.join([release, "/usr/local/bin", "/usr/bin", "/bin",
                                       env.get("PATH", "")])
        env["PYTHONPATH"] = os.path.join(release, "python")
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        for block in blocks:
            try:
                done = subprocess.run(["bash", "-e", "-c", block.text], cwd=scratch, env=env,
                                      stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, timeout=BLOCK_TIMEOUT_S)
            except subprocess.TimeoutExpired as timeout:
                output = (timeout.output or b"").decode("utf-8", "replace")
                return f"{block.page}:{block.line}: timed out after {BLOCK_TIMEOUT_S} s\n{output}"
            if done.returncode != 0:
                output = done.stdout.decode("utf-8", "replace")
                return (f"{block.page}:{block.line}: the block exited with code "
                        f"{done.returncode}\n--- block ---\n{block.text}--- output ---\n{output}")
        return None
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def check(root, build_dir, run_commands, jobs, quiet=False):
    """Checks every page; unless quiet, prints each failure and a closing count. Returns the
    failures."""
    blocks, problems = [], unindexed_pages(root)
    for page in pages(root):
        found, trouble = scan(root, page)
        blocks += found
        problems += trouble
    to_run = [b for b in blocks if b.skip_reason is None]
    skipped = len(blocks) - len(to_run)
    by_page = {}
    for block in to_run:
        by_page.setdefault(block.page, []).append(block)
    passed = 0
    if run_commands:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            for report in pool.map(lambda page: run_page(by_page[page], root, build_dir), by_page):
                if report is None:
                    passed += 1
                else:
                    problems.append(report)
    if quiet:
        return problems
    for problem in problems:
        print(problem, file=sys.stderr)
    ran = f"{len(to_run)} sh blocks on {len(by_page)} pages" if run_commands else "commands not run"
    print(f"docs: {passed} passed, {len(problems)} failed, {skipped} skipped ({ran}; a pass is a "
          f"page whose blocks all ran, a failure a page's failing block or a broken link; skipped "
          f"counts blocks marked not run)")
    return problems


def self_test():
    """Checks the checker on pages made for it: each kind of fault must be reported."""
    root = tempfile.mkdtemp(prefix="raycast-docs-selftest-")
    try:
        for name in LINKED_FOLDERS + ("docs",):
            os.mkdir(os.path.join(root, name))
        build = os.path.join(root, "build", "release")
        os.makedirs(build)
        with open(os.path.join(root, "docs", "page.md"), "w", encoding="utf-8") as f:
            f.write("# Page\n[fine](../README.md) [gone](missing.md) `[code](nowhere.md)`\n"
                    "```sh\ntest -d scenes && test -d build/release\n```\n"
                    "```sh\ntrue\nfalse\necho unreachable\n```\n"
                    "<!-- not run: needs a peer -->\n```sh\nexit 3\n```\n"
                    "<!-- not run: -->\n```sh\ntrue\n```\n")
        with open(os.path.join(root, "docs", "README.md"), "w", encoding="utf-8") as f:
            f.write("# Index\n[README](../README.md)\n")
        with open(os.path.join(root, "README.md"), "w", encoding="utf-8") as f:
            # Blocks of one page share its scratch folder, in order.
            f.write("# A `b`, c\n[docs](docs/page.md#page) [no](docs/page.md#nope) [me](#a-b-c)\n"
                    "```sh\necho made > made.txt\n```\n"
                    "```sh\ngrep -q made made.txt\n```\n")
        problems = check(root, build, True, 2, quiet=True)
        expected = ["docs/page.md:2: link to a missing file: missing.md",
                    "docs/page.md:6: the block exited with code 1",
                    "docs/page.md:15: `<!-- not run: -->` needs a reason",
                    "README.md:2: link to a missing heading: docs/page.md#nope",
                    "docs/README.md: the index does not link docs/page.md"]
        unmet = [e for e in expected if not any(p.startswith(e) for p in problems)]
        if unmet or len(problems) != len(expected):
            print("self-test FAILED: expected", expected, "got", problems, file=sys.stderr)
            return 1
        print("self-test: 1 passed, 0 failed")
        return 0
    finally:
        shutil.rmtree(root, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--root", default=here, help="the repository (default: this script's)")
    parser.add_argument("--build-dir", help="the release build (default: ROOT/build/release)")
    parser.add_argument("--links-only", action="store_true", help="check links, run nothing")
    parser.add_argument("--jobs", type=int, default=2, help="pages run at once (default 2)")
    parser.add_argument("--self-test", action="store_true", help="check the checker itself")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    root = os.path.abspath(args.root)
    build_dir = os.path.abspath(args.build_dir or os.path.join(root, "build", "release"))
    if not args.links_only and not os.path.isdir(build_dir):
        print(f"check_docs: no build folder {build_dir} (build the release preset)",
              file=sys.stderr)
        return 2
    return 1 if check(root, build_dir, not args.links_only, max(1, args.jobs)) else 0


if __name__ == "__main__":
    sys.exit(main())
