#!/usr/bin/env python3
"""Checks the include rules between the folders of host/methods/ and kernels/.

A method is one folder of host code and one of kernels; it includes no other method's folder.
Shared code lives in shared folders by concept:

- host/methods/: `caching/` (the record-caching pipeline: the record store, placement, record
  batches, the splat and render pass, and the lobe caches' framework), `grid/` (the irradiance
  vector grid) and `temporal/` (temporal caching, a wrapper over the record caches) are shared;
  every other folder is a method's. A method's folder includes only its own folder, the shared
  folders and the files of host/methods/ itself (the method interface and registry); a shared
  folder, and host/methods/ itself but for its registry, includes no method's folder.
- kernels/: `common/`, `shared/`, `caching/` and `temporal/` are shared; a method's folder
  includes only itself and the shared folders; a shared folder includes no method's folder.
- No file in a shared folder is named for a method (`ic_*`, `rc_*`, `sdrc_*`, `decomp_*`,
  `pt_*`, or a method folder's name): shared code is named for its concept (grid/'s concept, the
  irradiance vector grid, is also the ivg methods' folder's name). kernels/shared/, the
  host/device contract, declares each method's layout under the method's name and is exempt.
- No include cycle between folders.

Prints one line per broken rule, `file:line: include: why`, and exits with status 1 when there is
any. Standard library only.

    tools/check_includes.py
"""

import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')

TREES = {
    # tree: (prefix of an include naming one of its folders, shared folders)
    "host/methods": ("methods/", {"caching", "grid", "temporal"}),
    "kernels": ("", {"common", "shared", "caching", "temporal"}),
}
# The file of host/methods/ itself that may include every method's folder: the registry.
ROOT_MAY_INCLUDE_METHODS = {"registry.cpp"}
# Shared folders whose files may carry a method's name: the host/device contract.
NAMED_FOR_METHODS = {("kernels", "shared")}
# The concept a shared folder is named for, where a method's folder carries the same name (the
# irradiance vector grid is grid/'s concept and the ivg methods' folder's name).
SHARED_CONCEPTS = {"grid": "irradiance_vector_grid"}
# Prefixes that name a method, beside its folder's name.
METHOD_PREFIXES = ("ic_", "rc_", "sdrc_", "decomp_", "pt_")


def folders(tree):
    base = os.path.join(ROOT, tree)
    return sorted(d for d in os.listdir(base) if os.path.isdir(os.path.join(base, d)))


def includes(path):
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            match = INCLUDE.match(line)
            if match:
                yield number, match.group(1)


def folder_of(include, prefix, known):
    """The folder of `tree` that `include` names, or None."""
    if not include.startswith(prefix):
        return None
    parts = include[len(prefix):].split("/")
    return parts[0] if len(parts) > 1 and parts[0] in known else None


def named_for_method(name, methods):
    """Whether a file name starts with a method's prefix or a method folder's name."""
    return name.startswith(METHOD_PREFIXES) or any(name.startswith(m) for m in methods)


def check_root(tree, prefix, known, shared, problems):
    """The files of the tree's root (host/methods/ itself) include no method's folder."""
    base = os.path.join(ROOT, tree)
    for name in sorted(os.listdir(base)):
        path = os.path.join(base, name)
        if not os.path.isfile(path) or name in ROOT_MAY_INCLUDE_METHODS:
            continue
        for number, include in includes(path):
            target = folder_of(include, prefix, known)
            if target is not None and target not in shared:
                problems.append(f"{os.path.relpath(path, ROOT)}:{number}: {include}: "
                                "the methods' interface includes a method's folder")


def check_tree(tree, problems, edges):
    prefix, shared = TREES[tree]
    known = set(folders(tree))
    methods = sorted(known - shared)
    if tree == "host/methods":
        check_root(tree, prefix, known, shared, problems)
    for folder in sorted(known):
        for dirpath, _, files in os.walk(os.path.join(ROOT, tree, folder)):
            for name in sorted(files):
                path = os.path.join(dirpath, name)
                if not name.endswith((".h", ".cpp", ".cl")):
                    continue
                if (folder in shared and (tree, folder) not in NAMED_FOR_METHODS
                        and not name.startswith(SHARED_CONCEPTS.get(folder, "\0"))
                        and named_for_method(name, methods)):
                    problems.append(f"{os.path.relpath(path, ROOT)}: a file named for a method "
                                    "in a shared folder")
                for number, include in includes(path):
                    target = folder_of(include, prefix, known)
                    if target is None or target == folder:
                        continue
                    edges.setdefault((tree, folder), set()).add((tree, target))
                    if target in shared:
                        continue
                    why = ("a shared folder includes a method's folder" if folder in shared
                           else "a method includes another method's folder")
                    problems.append(f"{os.path.relpath(path, ROOT)}:{number}: {include}: {why}")


def find_cycle(edges):
    """A cycle of folders as a list, or None."""
    state = {}

    def visit(node, path):
        state[node] = 1
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                return path[path.index(nxt):] + [nxt] if nxt in path else [node, nxt]
            if nxt not in state:
                found = visit(nxt, path + [nxt])
                if found:
                    return found
        state[node] = 2
        return None

    for node in sorted(edges):
        if node not in state:
            found = visit(node, [node])
            if found:
                return found
    return None


def main():
    problems = []
    edges = {}
    for tree in TREES:
        check_tree(tree, problems, edges)
    cycle = find_cycle(edges)
    if cycle:
        problems.append("include cycle: " + " -> ".join(f"{t}/{f}" for t, f in cycle))
    for line in problems:
        print(line)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
