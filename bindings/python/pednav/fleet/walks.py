# SPDX-License-Identifier: Apache-2.0
"""The walks of a fleet run: a folder of recordings or a manifest."""
import csv
import fnmatch
import json
import os


class Walk:
    """One recording to reprocess: name, input path, optional truth (path,
    kind as `pednav eval --kind`), optional mount and reader format."""

    def __init__(self, name, input, truth=None, kind="auto", mount=None, format="auto"):
        self.name = name
        self.input = input
        self.truth = truth
        self.kind = kind
        self.mount = mount
        self.format = format

    def as_dict(self):
        return {"name": self.name, "input": self.input, "truth": self.truth, "kind": self.kind,
                "mount": self.mount, "format": self.format}

    def __repr__(self):
        return "Walk(%r, %r)" % (self.name, self.input)


def _walk_from(entry, base, where):
    if "input" not in entry:
        raise ValueError("%s: a walk needs \"input\"" % where)
    unknown = set(entry) - {"name", "input", "truth", "kind", "mount", "format"}
    if unknown:
        raise ValueError("%s: unknown key %s (expected name, input, truth, kind, mount, format)"
                         % (where, sorted(unknown)[0]))

    def resolve(p):
        return p if p is None or os.path.isabs(p) else os.path.normpath(os.path.join(base, p))

    name = entry.get("name") or os.path.splitext(os.path.basename(entry["input"].rstrip("/")))[0]
    kind = entry.get("kind") or "auto"
    truth = entry.get("truth") or None
    if truth is not None and not kind.startswith("loop"):
        truth = resolve(truth)
    return Walk(name, resolve(entry["input"]), truth, kind, entry.get("mount") or None,
                entry.get("format") or "auto")


def read_manifest(path):
    """Walks of a manifest: JSON {"walks": [{"name", "input", "truth",
    "kind", "mount", "format"}, ...]} or a CSV with those columns (input
    required); paths relative to the manifest."""
    base = os.path.dirname(os.path.abspath(path))
    if path.endswith(".json"):
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        if not isinstance(doc, dict) or not isinstance(doc.get("walks"), list):
            raise ValueError(path + ": expected an object with a \"walks\" array")
        walks = [_walk_from(w, base, "%s: /walks/%d" % (path, i)) for i, w in enumerate(doc["walks"])]
    else:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        walks = [_walk_from({k: v for k, v in row.items() if v}, base, "%s:%d" % (path, i + 2))
                 for i, row in enumerate(rows)]
    names = [w.name for w in walks]
    duplicate = next((n for n in names if names.count(n) > 1), None)
    if duplicate:
        raise ValueError(path + ": two walks are named " + duplicate)
    return walks


def find_walks(folder, pattern="*.csv"):
    """Walks of a folder: each sub-folder written by `pednav sim` (input.csv,
    evaluated against its truth.csv), and each file matching `pattern`
    (no truth)."""
    walks = []
    for entry in sorted(os.listdir(folder)):
        path = os.path.join(folder, entry)
        if os.path.isdir(path) and os.path.exists(os.path.join(path, "input.csv")):
            truth = os.path.join(path, "truth.csv")
            walks.append(Walk(entry, os.path.join(path, "input.csv"), truth if os.path.exists(truth) else None,
                              "sim" if os.path.exists(truth) else "auto"))
        elif os.path.isfile(path) and fnmatch.fnmatch(entry, pattern):
            walks.append(Walk(os.path.splitext(entry)[0], path))
    return walks


def load_walks(source, pattern="*.csv"):
    """Walks of a folder or a manifest file."""
    if os.path.isdir(source):
        return find_walks(source, pattern)
    if os.path.isfile(source):
        return read_manifest(source)
    raise FileNotFoundError("no folder or manifest " + source)
