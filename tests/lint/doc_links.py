#!/usr/bin/env python3
"""Checks the links of ochre's documentation: that every relative link leads somewhere.

1. Every relative Markdown link and image in README.md and docs/**/*.md (inline `[text](target)` and
   reference definitions `[label]: target`; fenced code blocks and `code spans` are skipped): the target
   file or directory exists, relative to the linking file; when the link has a #anchor and the target is
   a Markdown file (or the link is `#anchor` alone, into the same file), a heading of that file has that
   anchor.
2. Every reference to a Markdown file with an anchor (`NAME.md`, then `#` and the anchor) in the sources (*.cpp, *.h, *.py, *.sh, *.cmake, CMakeLists.txt, any
   line: comments, docstrings and messages alike): `docs/NAME.md` resolves against the source tree;
   another path (`tools.md`, `materials/powder.md`) against docs/, else to the one file under docs/ whose
   path ends with it. The anchor must exist there.

Anchors follow GitHub's rules: the heading's text as rendered (code spans, emphasis and links reduced to
their text, HTML tags dropped), lowercased, every character that is not a letter, digit, underscore,
hyphen or space removed, spaces turned into hyphens; a repeated anchor gets -1, -2, ... in order of
appearance. `<a name="...">` and `<a id="...">` anchors count too.

Prints each broken link as FILE:LINE: message. Exit status 0 when every link resolves, 1 otherwise.
Standard library only. Usage: doc_links.py SOURCE_DIR
"""

import pathlib
import re
import sys
import urllib.parse

SOURCE_SUFFIXES = {".cpp", ".h", ".py", ".sh", ".cmake"}
SKIPPED_DIRECTORIES = {".git", "build", "node_modules", "__pycache__"}

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
ATX_HEADING = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?[ \t]*$")
SETEXT_UNDERLINE = re.compile(r"^ {0,3}(=+|-+)[ \t]*$")
HTML_ANCHOR = re.compile(r"<a\s+[^>]*?(?:name|id)\s*=\s*[\"']([^\"']+)[\"']", re.I)
CODE_SPAN = re.compile(r"(`+)(.+?)\1", re.S)
REFERENCE_DEFINITION = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)")
# A code reference: a path ending in .md, then #anchor.
CODE_REFERENCE = re.compile(r"(?<![\w./-])((?:\.\./|\./)?[\w.-]+(?:/[\w.-]+)*\.md)#([\w-]+)")


def github_slug(text):
    """The anchor GitHub gives a heading whose rendered text is `text` (before de-duplication)."""
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in "_- ")
    return text.replace(" ", "-")


def rendered_heading_text(markdown):
    """The text of a heading's inline Markdown as GitHub renders it (near enough for anchors)."""
    spans = []

    def keep_code(match):
        spans.append(match.group(2).strip() if match.group(2).strip() else match.group(2))
        return f"\x00{len(spans) - 1}\x00"

    text = CODE_SPAN.sub(keep_code, markdown)
    text = re.sub(r"!\[([^\]]*)\]\([^)]*\)", r"\1", text)  # images: their alt text
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links: their text
    text = re.sub(r"\[([^\]]*)\]\[[^\]]*\]", r"\1", text)  # reference links
    text = re.sub(r"<[^>]+>", "", text)  # HTML tags
    text = re.sub(r"(\*+|(?<!\w)_+|_+(?!\w))", "", text)  # emphasis delimiters
    return re.sub("\x00(\\d+)\x00", lambda m: spans[int(m.group(1))], text)


def markdown_lines(text):
    """(line number, line) of the lines outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        match = FENCE.match(line)
        if fence is None:
            if match:
                fence = match.group(1)
                continue
            yield number, line
        elif match and match.group(1)[0] == fence[0] and len(match.group(1)) >= len(fence) and \
                not line.strip()[len(match.group(1)):].strip():
            fence = None


def anchors_of(text):
    """Every anchor of a Markdown text: its headings' (GitHub slugs, de-duplicated) and HTML anchors."""
    anchors, counts = set(), {}
    previous = ""
    for _, line in markdown_lines(text):
        heading = None
        match = ATX_HEADING.match(line)
        if match:
            heading = re.sub(r"[ \t]+#+[ \t]*$", "", match.group(2) or "")
            if re.fullmatch(r"#+", heading or ""):
                heading = ""
        elif SETEXT_UNDERLINE.match(line) and previous.strip() and not ATX_HEADING.match(previous) and \
                not previous.lstrip().startswith(("|", "-", "*", "+", ">")) and \
                not re.match(r"^\s*\d+[.)]\s", previous):
            heading = previous.strip()
        if heading is not None:
            slug = github_slug(rendered_heading_text(heading))
            if slug in counts:
                counts[slug] += 1
                anchors.add(f"{slug}-{counts[slug]}")
            else:
                counts[slug] = 0
                anchors.add(slug)
        anchors.update(HTML_ANCHOR.findall(line))
        previous = line
    return anchors


def inline_link_targets(line):
    """The targets of the inline links and images of one line of Markdown, code spans removed."""
    line = CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)
    targets = []
    at = 0
    while True:
        start = line.find("](", at)
        if start < 0:
            return targets
        # The destination runs to the matching parenthesis (balanced parentheses are allowed in it).
        depth, end = 1, start + 2
        while end < len(line) and depth:
            depth += {"(": 1, ")": -1}.get(line[end], 0)
            end += 1
        destination = line[start + 2:end - 1].strip()
        if destination.startswith("<") and ">" in destination:
            destination = destination[1:destination.index(">")]
        else:
            destination = destination.split()[0] if destination.split() else ""
        targets.append(destination)
        at = end


def is_external(target):
    return re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target) is not None or target.startswith("//")


class Checker:
    def __init__(self, root):
        self.root = root
        self.docs = root / "docs"
        self.anchor_cache = {}
        self.problems = []

    def anchors(self, path):
        path = path.resolve()
        if path not in self.anchor_cache:
            self.anchor_cache[path] = anchors_of(path.read_text(encoding="utf-8"))
        return self.anchor_cache[path]

    def report(self, path, number, message):
        self.problems.append(f"{path.relative_to(self.root)}:{number}: {message}")

    def check_anchor(self, path, number, link, target, anchor):
        if anchor and target.suffix == ".md" and anchor not in self.anchors(target):
            self.report(path, number, f"{link}: no heading with the anchor #{anchor} in "
                                      f"{target.resolve().relative_to(self.root.resolve())}")

    def check_markdown(self, path):
        text = path.read_text(encoding="utf-8")
        for number, line in markdown_lines(text):
            targets = inline_link_targets(line)
            definition = REFERENCE_DEFINITION.match(line)
            if definition:
                targets.append(definition.group(1).strip("<>"))
            for link in targets:
                if not link or is_external(link):
                    continue
                file_part, _, anchor = link.partition("#")
                file_part = urllib.parse.unquote(file_part)
                anchor = urllib.parse.unquote(anchor)
                if file_part.startswith("/"):
                    self.report(path, number, f"{link}: absolute path (links must be relative)")
                    continue
                target = (path.parent / file_part) if file_part else path
                if not target.exists():
                    self.report(path, number, f"{link}: {file_part} does not exist")
                    continue
                self.check_anchor(path, number, link, target, anchor)

    def resolve_code_reference(self, reference):
        """The Markdown file a reference in the sources means, or None when none or several match."""
        if reference.startswith("docs/"):
            target = self.root / reference
            return target if target.exists() else None
        direct = self.docs / reference
        if direct.exists():
            return direct
        name = pathlib.PurePosixPath(reference.lstrip("./"))
        matches = [p for p in self.docs.rglob("*.md")
                   if pathlib.PurePosixPath(p.relative_to(self.docs).as_posix()).parts[-len(name.parts):]
                   == name.parts]
        return matches[0] if len(matches) == 1 else None

    def check_source(self, path):
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            return
        for number, line in enumerate(text.split("\n"), 1):
            for reference, anchor in CODE_REFERENCE.findall(line):
                target = self.resolve_code_reference(reference)
                if target is None:
                    self.report(path, number, f"{reference}#{anchor}: no such document under docs/ "
                                              f"(or more than one)")
                    continue
                self.check_anchor(path, number, f"{reference}#{anchor}", target, anchor)


def walk(root):
    for path in sorted(root.iterdir()):
        if path.is_dir():
            if path.name not in SKIPPED_DIRECTORIES and not path.is_symlink():
                yield from walk(path)
        else:
            yield path


def main(argv):
    if len(argv) != 2:
        print("usage: doc_links.py SOURCE_DIR", file=sys.stderr)
        return 2
    root = pathlib.Path(argv[1])
    if not (root / "docs").is_dir():
        print(f"doc_links.py: {root} has no docs/ folder", file=sys.stderr)
        return 2
    checker = Checker(root)
    markdown = [root / "README.md"] if (root / "README.md").exists() else []
    markdown += sorted((root / "docs").rglob("*.md"))
    for path in markdown:
        checker.check_markdown(path)
    sources = 0
    for path in walk(root):
        if path.suffix in SOURCE_SUFFIXES or path.name == "CMakeLists.txt":
            sources += 1
            checker.check_source(path)
    for problem in checker.problems:
        print(problem)
    if checker.problems:
        print(f"{len(checker.problems)} broken link(s) in {len(markdown)} Markdown files and {sources} sources")
        return 1
    print(f"doc_links.py: every link resolves ({len(markdown)} Markdown files, {sources} sources)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
