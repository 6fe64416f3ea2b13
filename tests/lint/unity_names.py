#!/usr/bin/env python3
"""Checks the two naming rules that ochre's unity builds rely on (docs/architecture.md, "Building against
Debian 12's packages"):

1. In a library or tool, no name declared at the top of one file's anonymous namespace is declared in another
   file of the same target. Two such helpers end up in one translation unit, where an exact repeat is a
   compile error but two overloads are not: a call could silently bind to the other file's helper.
2. A test file (one with TEST macros) keeps its code in a namespace named after the file
   (namespace ochre::test::split_merge_test), so test files may reuse helper names freely.
And the one naming scheme of test files (docs/architecture.md, "Tests"): a file with TEST macros is named
x_test.cpp, and a file named so has them.

Exit status 0 when all hold, 1 with a list of the offending names and files otherwise.
Usage: unity_names.py SOURCE_DIR
"""

import collections
import pathlib
import re
import sys

# The targets built as unity builds, as (directory, recursive, files left out): each directory is one
# target's sources, or the part of one that may share a translation unit.
LIBRARY_DIRECTORIES = [
    ("spectra", False, set()),
    ("materials", True, set()),
    ("renderer", False, set()),
    ("tools/ochre", False, set()),
    ("tools/brdf", False, {"ochre_brdf.cpp", "material_probe.cpp"}),
    ("tools/vgroove", False, {"ochre_vgroove.cpp"}),
    ("tools/fit", False, {"ochre_fit.cpp"}),
    ("tools/regress", False, {"ochre_regress.cpp"}),
    ("tools/halfspace", False, {"ochre_halfspace.cpp"}),
    ("tools/python", False, set()),
]
# The test folders, searched with their sub-folders (tests/CMakeLists.txt: one executable per folder, the
# unit tests in folders that mirror the sources).
TEST_DIRECTORIES = ["cli", "renderer", "materials", "spectra", "tools"]

DECLARATION = re.compile(r"^[^(=;{]*?([A-Za-z_]\w*)\s*(\(|=|\{|;|\[)")
TYPE = re.compile(r"^(?:struct|class|enum class|enum|union)\s+([A-Za-z_]\w*)")
TEST_MACRO = re.compile(r"^\s*(TEST|TEST_F|TEST_P|TYPED_TEST)\(", re.M)
NAMESPACE_OPENER = re.compile(r"^namespace (ochre(?:::\w+)*) \{$", re.M)


def anonymous_names(path):
    """Names declared at the top level of the file's anonymous namespaces (clang-formatted code: such
    declarations start in column 0 between `namespace {` and `}  // namespace`)."""
    names = set()
    inside = False
    for line in path.read_text(encoding="utf-8").split("\n"):
        if line == "namespace {":
            inside = True
            continue
        if line == "}  // namespace":
            inside = False
            continue
        if not inside or not line or line[0] in " \t}/#" or line.startswith(("template", "namespace ", "using ")):
            continue
        match = TYPE.match(line) or DECLARATION.match(line)
        if match and match.group(1) != "operator":
            names.add(match.group(1))
    return names


def library_problems(source):
    problems = []
    for directory, recursive, left_out in LIBRARY_DIRECTORIES:
        root = source / directory
        files = sorted(root.rglob("*.cpp") if recursive else root.glob("*.cpp"))
        owners = collections.defaultdict(list)
        for path in files:
            if path.name in left_out or "generator" in path.parts:
                continue
            for name in anonymous_names(path):
                owners[name].append(path.relative_to(source).as_posix())
        for name, paths in sorted(owners.items()):
            if len(paths) > 1:
                problems.append(f"{directory}: '{name}' is declared in the anonymous namespace of {', '.join(paths)}"
                                " (one target: fold the helper into a header or rename one)")
    return problems


def test_problems(source):
    problems = []
    for directory in TEST_DIRECTORIES:
        for path in sorted((source / "tests" / directory).rglob("*.cpp")):
            text = path.read_text(encoding="utf-8")
            has_tests = TEST_MACRO.search(text) is not None
            if has_tests != path.stem.endswith("_test"):
                problems.append(f"{path.relative_to(source).as_posix()}: " +
                                ("a test file is named x_test.cpp" if has_tests else
                                 "no TEST in it: only test files are named x_test.cpp"))
            if not has_tests:
                continue
            openers = NAMESPACE_OPENER.findall(text)
            if not openers:
                problems.append(f"{path.relative_to(source).as_posix()}: no namespace ochre...::{path.stem}")
            for opener in openers:
                if opener.split("::")[-1] != path.stem:
                    problems.append(f"{path.relative_to(source).as_posix()}: namespace {opener} should end in "
                                    f"::{path.stem} (the file's own namespace, for the unity build)")
    return problems


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    source = pathlib.Path(sys.argv[1])
    problems = library_problems(source) + test_problems(source)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} name(s) break the unity build's rules (docs/architecture.md)")
        return 1
    print("unity build naming rules hold")
    return 0


if __name__ == "__main__":
    sys.exit(main())
