#!/usr/bin/env python3
"""Checks that every relative link of the project's Markdown resolves.

Reads README.md, docs/**/*.md and scenes/**/*.md (or the files named on the command line) and,
for every inline link `[text](target)`, reference definition `[label]: target` and HTML
`src="..."`/`href="..."` outside code blocks and code spans, checks that

- a relative target names a file or folder that exists (relative to the linking file);
- an anchor (`file.md#anchor` or `#anchor`) names a heading of the target Markdown file, by
  GitHub's slugs: the heading's text without markup, lower-cased, every character that is not a
  letter, digit, space, `-` or `_` dropped, spaces turned into `-`, and `-1`, `-2`, ... appended
  to repeated slugs.

Absolute URLs (http:, https:, mailto:) are not checked. Prints one line per broken link,
`file:line: target: why`, and exits with status 1 when there is any. Standard library only.

    tools/check_doc_links.py [FILE.md ...]
"""

import glob
import os
import re
import sys
import urllib.parse

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^()\s>]*(?:\([^()\s]*\)[^()\s>]*)*)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_DEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
HTML_ATTR = re.compile(r"\b(?:src|href)\s*=\s*\"([^\"]*)\"")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:name|id)\s*=\s*\"([^\"]+)\"")


def markdown_files(paths):
    if paths:
        for p in paths:
            if not os.path.isfile(p):
                sys.exit("check_doc_links: %s: no such Markdown file" % p)
        return [os.path.abspath(p) for p in paths]
    files = [os.path.join(ROOT, "README.md")]
    for pattern in ("docs/**/*.md", "scenes/**/*.md"):
        files += sorted(glob.glob(os.path.join(ROOT, pattern), recursive=True))
    return [f for f in files if os.path.isfile(f)]


def lines_outside_fences(text):
    """(line number, line) of every line that is not inside a fenced or indented code block."""
    in_fence = False
    previous_blank = True
    in_indented = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        blank = not line.strip()
        # An indented code block starts after a blank line with four spaces or a tab; a list
        # item's continuation lines are indented too, but never follow a blank line here with
        # four spaces unless they are code, in this project's files.
        if in_indented and not blank and not (line.startswith("    ") or line.startswith("\t")):
            in_indented = False
        if not in_indented and previous_blank and (line.startswith("    ") or line.startswith("\t")) \
                and not line.lstrip().startswith(("-", "*", "|")) and not blank:
            in_indented = True
        previous_blank = blank
        if in_indented:
            continue
        yield number, line


def strip_code_spans(line):
    return CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)


def slug(heading):
    """GitHub's anchor for a heading's Markdown text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)   # links: their text
    text = re.sub(r"<[^>]+>", "", text)                          # HTML tags
    text = text.replace("`", "")
    text = re.sub(r"(\*\*|__|\*)", "", text)                     # emphasis markers (not _)
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in "-_ " or c == "_")
    return text.replace(" ", "-")


_anchor_cache = {}


def anchors(path):
    if path not in _anchor_cache:
        seen = {}
        found = set()
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for _, line in lines_outside_fences(text):
            for name in HTML_ANCHOR.findall(line):
                found.add(name)
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            count = seen.get(base, 0)
            seen[base] = count + 1
            found.add(base if count == 0 else "%s-%d" % (base, count))
        _anchor_cache[path] = found
    return _anchor_cache[path]


def check_target(source, target):
    """None when the target resolves, else why not."""
    if not target or re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
        return None  # empty, or an absolute URL (http:, mailto:, ...)
    path_part, _, anchor = target.partition("#")
    path_part = urllib.parse.unquote(path_part)
    anchor = urllib.parse.unquote(anchor)
    if path_part.startswith("/"):
        return "absolute path (use a relative one)"
    dest = os.path.normpath(os.path.join(os.path.dirname(source), path_part)) if path_part \
        else source
    if not os.path.exists(dest):
        return "no such file %s" % os.path.relpath(dest, ROOT)
    if anchor:
        if not dest.endswith(".md") or os.path.isdir(dest):
            return None  # a line anchor into source (#L10) or similar: not checked
        if anchor not in anchors(dest):
            return "no heading with anchor #%s in %s" % (anchor, os.path.relpath(dest, ROOT))
    return None


def check_file(path):
    problems = []
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for number, line in lines_outside_fences(text):
        visible = strip_code_spans(line)
        targets = [m.group(1) for m in INLINE_LINK.finditer(visible)]
        m = REFERENCE_DEF.match(visible)
        if m:
            targets.append(m.group(1))
        targets += HTML_ATTR.findall(visible)
        for target in targets:
            why = check_target(path, target)
            if why:
                problems.append("%s:%d: %s: %s" % (os.path.relpath(path, ROOT), number, target, why))
    return problems


def main(argv):
    files = markdown_files(argv)
    problems = []
    for path in files:
        problems += check_file(path)
    for problem in problems:
        print(problem)
    print("check_doc_links: %d files, %d broken links" % (len(files), len(problems)),
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
