#!/usr/bin/env python3
"""Downloads the held-out POV-Ray scenes named in scenes.json from GitHub into a folder.

    python3 bench/pov-heldout/fetch.py --out /work/heldout/scenes [--manifest FILE]

Every file (the scene and the extra files it reads) comes from
https://raw.githubusercontent.com/OWNER/REPO/COMMIT/PATH, pinned to the manifest's commit, and is
written to OUT/OWNER__REPO/PATH, so each scene keeps its folder layout and its relative
#include paths work. Files already there are skipped. The scenes belong to their authors: keep
them outside the repository.
"""
import argparse
import json
import os
import sys
import time
import urllib.error
import urllib.parse
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
RAW = "https://raw.githubusercontent.com/%s/%s/%s"


def files(manifest):
    """(repo, commit, path) of every file the manifest names, each once."""
    seen = set()
    for scene in manifest:
        for path in [scene["path"]] + scene.get("extra", []):
            key = (scene["repo"], scene["commit"], path)
            if key not in seen:
                seen.add(key)
                yield key


def destination(out, repo, path):
    """OUT/OWNER__REPO/PATH; refuses paths that would leave OUT."""
    base = os.path.abspath(os.path.join(out, repo.replace("/", "__")))
    target = os.path.abspath(os.path.join(base, path))
    if not target.startswith(base + os.sep):
        raise ValueError("path leaves the output folder: %s" % path)
    return target


def download(url, target, attempts=3, timeout=30):
    """Writes url's bytes to target through a temporary file, retrying passing faults."""
    for attempt in range(attempts):
        try:
            with urllib.request.urlopen(url, timeout=timeout) as response:
                data = response.read()
            break
        except urllib.error.HTTPError as e:
            if e.code == 404 or attempt == attempts - 1:
                raise
        except (urllib.error.URLError, TimeoutError, ConnectionError):
            if attempt == attempts - 1:
                raise
        time.sleep(2 ** attempt)
    os.makedirs(os.path.dirname(target), exist_ok=True)
    with open(target + ".part", "wb") as f:
        f.write(data)
    os.replace(target + ".part", target)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True, help="folder to write OWNER__REPO/PATH into")
    ap.add_argument("--manifest", default=os.path.join(HERE, "scenes.json"))
    a = ap.parse_args()
    with open(a.manifest) as f:
        manifest = json.load(f)["scenes"]
    got = skipped = 0
    failed = []
    for repo, commit, path in files(manifest):
        target = destination(a.out, repo, path)
        if os.path.exists(target):
            skipped += 1
            continue
        url = RAW % (repo, commit, urllib.parse.quote(path, safe="/"))
        try:
            download(url, target)
            got += 1
        except (urllib.error.URLError, TimeoutError, ConnectionError, OSError) as e:
            failed.append((url, str(e)))
    print("%d downloaded, %d already there, %d failed" % (got, skipped, len(failed)))
    for url, why in failed:
        print("  failed: %s (%s)" % (url, why), file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
