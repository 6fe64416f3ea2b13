"""Runs the N-th ```python block of a markdown document (docs/python.md) as a script, in a fresh scratch
directory. The examples may read OCHRE_SOURCE_DIR (the source tree, for its scenes) from the environment."""

import os
import re
import sys
import tempfile


def examples(text):
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def main():
    document, index = sys.argv[1], int(sys.argv[2])
    with open(document) as f:
        blocks = examples(f.read())
    if index >= len(blocks):
        sys.exit(f"{document} has {len(blocks)} python examples, no example {index}")
    with tempfile.TemporaryDirectory(dir=os.getcwd()) as scratch:
        os.chdir(scratch)
        code = compile(blocks[index], f"{os.path.basename(document)} example {index}", "exec")
        exec(code, {"__name__": "__main__"})
    print(f"{os.path.basename(document)} example {index}: ran")


if __name__ == "__main__":
    main()
