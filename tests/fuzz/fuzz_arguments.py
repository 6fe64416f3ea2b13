#!/usr/bin/env python3
"""Fuzzes the command lines of ochre's programs (docs/validation.md, "Fuzzing").

Each iteration takes a valid command line of one program (ochre render, ochre merge, ochre-diff,
ochre-regress, ochre-converge, ochre-bench, ochre-brdf, ochre-vgroove, ochre-fit, ochre-halfspace) on
small inputs in a scratch directory, mutates it (an option's value replaced by a hostile one, an option of
the program's --help added with such a value, a value or a positional dropped, an option repeated, two
arguments swapped) and runs it. A finding is:
- an exit code other than 0, 2, 3 (a time limit) and 4 (a failed check), or death by a signal: 1 is an
  internal error, and no command line may cause one;
- a run that exceeds the time limit (a hang: the base commands take well under a second);
- exit 2 with a message that is not `PROG: error: ...` (every refusal names what is wrong);
- exit 2 (bad input) that wrote, removed or changed a file of the scratch directory, or left a temporary
  file (nothing is written on bad input; nothing already written is lost);

Usage: fuzz_arguments.py [--bin DIR] [--seconds S | --iterations N] [--seed S] [--repeat SEED:ITERATION]
       fuzz_arguments.py --selftest
Exits 0 when nothing was found, 1 on a finding (each printed with the command that repeats it).
"""

import argparse
import hashlib
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

TIMEOUT = 60.0  # seconds per run: a hang, not a slow run, for the small inputs below

SCENE = """{
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov": 40},
  "film": {"resolution": [8, 6]},
  "integrator": {"spp": 4, "max_depth": 3},
  "materials": {"grey": {"type": "lambert", "color": 0.5}},
  "shapes": [{"type": "sphere", "radius": 1, "material": "grey"}],
  "lights": [{"type": "environment", "radiance": 1}]
}
"""

MATERIAL = '{"type": "lambert", "color": 0.5}\n'
PAIRS = "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm\n0,0,1,0.3,0,0.95,550\n"

# Values that are malformed, out of range or hostile for some option; none is a valid but costly request,
# so that a run over the time limit is a hang.
HOSTILE = [
    "", "-1", "-0", "0", "nan", "NaN", "inf", "-inf", "1e309", "-1e309", "1e-320",
    "18446744073709551616", "-9223372036854775809", "0x10", "1x", " 1", "1 ",
    "1,2", "1:2", "3:1", "0:0", "1/0", "0/0", "2/1", "1/2/3", "0x0", "8x", "x8", "-8x8", "65537x8", "1.5",
    "1e3", "abc", "true", "-", "--", "---", "--x", "=", "a=b", "=b", "a=", "%s%s%n", "../", "/", ".",
    "/dev/null", "/dev/zero", "/dev/full", "/proc/self/mem", "/nonexistent/dir/file.exr", "fifo", "adir",
    "link", "scene.json", "a.exr", "out.exr", "ü", "\u202e", "a" * 5000, "1" * 400, "-" + "9" * 400,
]

# (program, base arguments, protected inputs). Paths are relative to the scratch directory.
def base_commands():
    quick = ["--resolution", "8x6", "--spp", "2", "-q"]
    return [
        ("ochre", ["render", "scene.json", "-o", "out.exr", "--png", "out.png"] + quick),
        ("ochre", ["render", "scene.json", "--part", "0/2", "-o", "p.exr"] + quick),
        ("ochre", ["render", "scene.json", "--tile", "1/2x1", "-o", "t.exr", "--checkpoint-interval", "1h"] + quick),
        ("ochre", ["render", "scene.json", "-o", "n.exr", "--noise-threshold", "0.1", "--spp", "32",
                   "--resolution", "8x6", "-q"]),
        ("ochre", ["render", "scene.json", "-o", "f.exr", "--frames", "2", "--fps", "24"] + quick),
        ("ochre", ["merge", "part0.exr", "part1.exr", "-o", "merged.exr", "-q"]),
        ("ochre-diff", ["a.exr", "b.exr", "--max-rmse", "1", "--heatmap", "heat.png"]),
        ("ochre-regress", ["suite", "--spp", "2", "--junit", "junit.xml"]),
        ("ochre-converge", ["scene.json", "--reference", "a.exr", "--spp", "1,2", "--csv", "c.csv",
                            "--width", "8", "--height", "6"]),
        ("ochre-brdf", ["eval", "--material", "material.json", "--input", "pairs.csv", "--output", "f.csv"]),
        ("ochre-brdf", ["albedo", "--material", "material.json", "--angles", "0", "45", "--samples", "1000"]),
        ("ochre-vgroove", ["directional", "--material", "Au", "--alpha", "90", "--theta", "30", "--phi", "0"]),
        ("ochre-vgroove", ["bihemispherical", "--material", "Si", "--alpha", "60"]),
        ("ochre-fit", ["powder", "--synthesize", "synthetic.csv"]),
        ("ochre-halfspace", ["--c", "0.5", "--mu", "0.5", "--phi", "0", "--paths", "200", "--output", "h.csv"]),
        ("ochre-bench", ["scene.json", "--spp", "1", "--seconds", "0.05", "--repeat", "1", "--threads", "1"]),
    ]


def run(bin_dir, program, args, cwd, timeout=None):
    timeout = TIMEOUT if timeout is None else timeout
    env = dict(os.environ, OCHRE_PROGRESS="off", OCHRE_CACHE_DIR=os.path.join(cwd, ".cache"))
    for attempt in range(5):
        try:
            r = subprocess.run([os.path.join(bin_dir, program)] + args, cwd=cwd, env=env, capture_output=True,
                               timeout=timeout, stdin=subprocess.DEVNULL)
            return r.returncode, (r.stdout + r.stderr).decode("utf-8", "replace")
        except subprocess.TimeoutExpired:
            return None, "timeout"
        except OSError:  # the program being rebuilt meanwhile (a long run beside a build): try again
            time.sleep(2.0)
    raise RuntimeError(f"cannot run {program}")


def prepare(bin_dir, root):
    """The scratch directory's inputs: a scene, two images, two parts, a regression suite, a material."""
    def write(name, text):
        with open(os.path.join(root, name), "w") as f:
            f.write(text)
    write("scene.json", SCENE)
    write("material.json", MATERIAL)
    write("pairs.csv", PAIRS)
    os.makedirs(os.path.join(root, "suite"))
    write("suite/scene.json", SCENE)
    os.mkfifo(os.path.join(root, "fifo"))
    os.makedirs(os.path.join(root, "adir"))
    os.symlink("scene.json", os.path.join(root, "link"))
    steps = [
        ("ochre", ["render", "scene.json", "-o", "a.exr", "-q", "--seed", "1"]),
        ("ochre", ["render", "scene.json", "-o", "b.exr", "-q", "--seed", "2"]),
        ("ochre", ["render", "scene.json", "--part", "0/2", "-o", "part0.exr", "-q"]),
        ("ochre", ["render", "scene.json", "--part", "1/2", "-o", "part1.exr", "-q"]),
        ("ochre-regress", ["suite", "--update", "--reference-spp", "8"]),
    ]
    for program, args in steps:
        code, output = run(bin_dir, program, args, root)
        if code != 0:
            raise RuntimeError(f"preparing the inputs: {program} {shlex.join(args)} failed:\n{output}")


def snapshot(root):
    """Every file and link of the scratch directory with a hash of its content (FIFOs by type only)."""
    files = {}
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d != ".cache"]
        for name in filenames + [d for d in dirnames if os.path.islink(os.path.join(dirpath, d))]:
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            if os.path.islink(path):
                files[rel] = "link:" + os.readlink(path)
            elif not os.path.isfile(path):
                files[rel] = "special"
            else:
                with open(path, "rb") as f:
                    files[rel] = hashlib.sha1(f.read()).hexdigest()
    return files


def options_of(bin_dir, program, args, cache={}):
    """The long options of the (sub)command's --help."""
    key = (program, args[0] if program in ("ochre", "ochre-brdf", "ochre-vgroove", "ochre-fit") else "")
    if key not in cache:
        command = [key[1]] if key[1] else []
        _, text = run(bin_dir, program, command + ["--help"], "/", 30)
        cache[key] = sorted(set(re.findall(r"^\s+(?:-\w,)?(--[a-z][a-z0-9-]*)", text, re.M)) - {"--help", "--version"})
    return cache[key]


def mutate(rng, bin_dir, program, args):
    args = list(args)
    sub = 1 if program in ("ochre", "ochre-brdf", "ochre-vgroove", "ochre-fit") else 0
    # ochre-bench without its scene benchmarks the default cave and box: minutes, not a hang.
    if program == "ochre-bench":
        sub = 1
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(["value", "value", "add", "add", "drop", "repeat", "swap", "flag"])
        positions = list(range(sub, len(args)))
        if kind == "value" and positions:
            args[rng.choice(positions)] = rng.choice(HOSTILE)
        elif kind == "add":
            options = options_of(bin_dir, program, args)
            if options:
                option = rng.choice(options)
                value = rng.choice(HOSTILE)
                args += [option, value] if rng.random() < 0.8 else [f"{option}={value}"]
        elif kind == "drop" and positions:
            del args[rng.choice(positions)]
        elif kind == "repeat" and positions:
            i = rng.choice(positions)
            args += args[i:i + 2]
        elif kind == "swap" and len(positions) > 1:
            i, j = rng.sample(positions, 2)
            args[i], args[j] = args[j], args[i]
        elif kind == "flag":
            options = options_of(bin_dir, program, args)
            if options:
                args.append(rng.choice(options))
    return args


def temporaries(files):
    return [f for f in files if ".tmp-" in os.path.basename(f)]


def check(bin_dir, program, args, root, before):
    """The finding of one run, or None."""
    code, output = run(bin_dir, program, args, root)
    after = snapshot(root)
    if code is None:
        return "hang (over %.0f s)" % TIMEOUT
    if code < 0:
        return f"killed by signal {-code}:\n{output[-2000:]}"
    if code not in (0, 2, 3, 4):
        return f"exit code {code}:\n{output[-2000:]}"
    if "internal error" in output:
        return f"an internal error reported with exit {code}:\n{output[-2000:]}"
    if code == 2:
        name = program
        if not re.search(rf"(^|\n){re.escape(name)}: error: .", output):
            return f"exit 2 without a '{name}: error: ...' message:\n{output[-2000:]}"
        added = sorted(set(after) - set(before))
        removed = sorted(set(before) - set(after))
        modified = sorted(p for p in before if p in after and before[p] != after[p])
        if added or removed or modified:
            return f"bad input (exit 2) changed files: added {added}, removed {removed}, modified {modified}:\n{output[-1000:]}"
    if temporaries(after):
        return f"temporary files left: {temporaries(after)}"
    return None


def reset_outputs(root, pristine, before):
    """Puts the scratch directory back as prepared: removes what a run wrote, restores what it replaced (a
    successful command may write over a file that was an input of others, e.g. `-o a.exr`)."""
    after = snapshot(root)
    for path in set(after) - set(before):
        full = os.path.join(root, path)
        if os.path.isdir(full) and not os.path.islink(full):
            shutil.rmtree(full)
        else:
            os.remove(full)
    for path, digest in before.items():
        if after.get(path) != digest and digest not in ("special",) and not digest.startswith("link:"):
            shutil.copy2(os.path.join(pristine, path), os.path.join(root, path))


def iteration(rng, bin_dir):
    program, args = rng.choice(base_commands())
    return program, mutate(rng, bin_dir, program, args)


def fuzz(bin_dir, seed, seconds, iterations, repeat=None):
    root = tempfile.mkdtemp(prefix="ochre-fuzz-args-")
    try:
        prepare(bin_dir, root)
        before = snapshot(root)
        pristine = root + ".pristine"
        shutil.copytree(root, pristine, symlinks=True, ignore=lambda d, names: [n for n in names if n == "fifo"])
        findings = 0
        start = time.monotonic()
        k = 0
        while True:
            if repeat is None:
                if iterations is not None and k >= iterations:
                    break
                if seconds is not None and time.monotonic() - start >= seconds:
                    break
            rng = random.Random(f"{seed}:{k}")
            program, args = iteration(rng, bin_dir)
            if repeat is None or k == repeat:
                finding = check(bin_dir, program, args, root, before)
                if finding:
                    findings += 1
                    print(f"FINDING (repeat with --seed {seed} --repeat {k}): {program} {shlex.join(args)}\n"
                          f"  {finding}\n", flush=True)
                reset_outputs(root, pristine, before)
                if repeat is not None:
                    break
            k += 1
        runs = k if repeat is None else 1
        print(f"fuzz_arguments: {runs} command line(s) from seed {seed} in {time.monotonic() - start:.1f} s, "
              f"{findings} finding(s)")
        return 1 if findings else 0
    finally:
        shutil.rmtree(root, ignore_errors=True)
        shutil.rmtree(root + ".pristine", ignore_errors=True)


def selftest(bin_dir):
    """The checks report what they must: a stub program that crashes, exits 1, hangs, writes on bad input or
    refuses without a message is each a finding; a clean refusal is not."""
    stubs = tempfile.mkdtemp(prefix="ochre-fuzz-args-selftest-")
    root = tempfile.mkdtemp(prefix="ochre-fuzz-args-root-")
    try:
        cases = {
            "crash": ("kill -SEGV $$", "killed by signal"),
            "internal": ("echo 'internal: internal error: bug' >&2; exit 1", "exit code 1"),
            "silent": ("exit 2", "without a"),
            "writes": ("echo x > written.txt; echo 'writes: error: no' >&2; exit 2", "changed files"),
            "clean": ("echo 'clean: error: --spp: must be positive' >&2; exit 2", None),
        }
        for name, (body, _) in cases.items():
            path = os.path.join(stubs, name)
            with open(path, "w") as f:
                f.write(f"#!/bin/sh\n{body}\n")
            os.chmod(path, 0o755)
        before = snapshot(root)
        ok = True
        for name, (_, expected) in cases.items():
            finding = check(stubs, name, [], root, before)
            reset_outputs(root, root, before)
            good = finding is None if expected is None else (finding is not None and expected in finding)
            print(f"selftest {name}: {'ok' if good else 'WRONG'} ({finding.splitlines()[0] if finding else 'no finding'})")
            ok = ok and good
        global TIMEOUT
        saved, TIMEOUT = TIMEOUT, 1.0
        path = os.path.join(stubs, "hang")
        with open(path, "w") as f:
            f.write("#!/bin/sh\nsleep 5\n")
        os.chmod(path, 0o755)
        finding = check(stubs, "hang", [], root, before)
        TIMEOUT = saved
        good = finding is not None and "hang" in finding
        print(f"selftest hang: {'ok' if good else 'WRONG'}")
        return 0 if ok and good else 1
    finally:
        shutil.rmtree(stubs, ignore_errors=True)
        shutil.rmtree(root, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.environ.get("OCHRE_BIN_DIR", "build/bin"))
    parser.add_argument("--seconds", type=float)
    parser.add_argument("--iterations", type=int)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--repeat", type=int, help="run only this iteration of --seed")
    parser.add_argument("--selftest", action="store_true")
    a = parser.parse_args()
    if a.selftest:
        return selftest(a.bin)
    if a.seconds is None and a.iterations is None and a.repeat is None:
        a.seconds = 15.0
    return fuzz(os.path.abspath(a.bin), a.seed, a.seconds, a.iterations, a.repeat)


if __name__ == "__main__":
    sys.exit(main())
