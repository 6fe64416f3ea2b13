"""Time to error of ochre and Blender Cycles on the same scene, side by side (docs/performance.md,
"Time to error against Cycles").

    PYENV_VERSION=system python3 tools/dev/cycles/run_benchmark.py --out build/cycles-bench \
        [--scene scenes/benchmark/cbox-matched.json] [--renderers cycles,ochre] [--ref-spp 4096]
        [--spps 8,16,32,64,128,256] [--repeat 3] [--threads 2] [--variant NAME:key=value,...]
        [--reuse-ref] [--lock /tmp/ochre-build.lock]

Each renderer is judged against its own converged reference (two renders of ref_spp/2 with seeds 1001
and 1002, averaged; a quarter of their squared difference estimates the reference's own relMSE, the
floor). The sweep renders every spp with seed 0, --repeat times, keeping the fastest run (the seed is
fixed, so the image is the same); the repeats run in rounds, each renderer and variant once per round, so
a machine whose speed drifts during the benchmark (a shared VM) slows all of them alike. Render seconds
exclude scene loading and BVH builds for both: Cycles' 'Render time (without synchronization)',
ochre-converge's in-process render timer.
relMSE = mean((x - ref)^2 / (ref^2 + 1e-2)) over pixels and R, G, B; C = relMSE x seconds, the
geometric mean over the swept spp (lower is better: relMSE ~ C / t), also with the floor subtracted.
relMSE at 1 s and at 10 s are read off the least-squares line through (log seconds, log relMSE) of the
sweep, marked * where that time lies outside the swept render times ('-' beyond 4x).
--summarise rewrites summary.md from OUT/results.csv and the reference halves in OUT/exr without rendering.
The luminance relMSE (Rec.709 Y, same epsilon) at --colour-spp shows how much of the error is colour noise.

An ochre variant NAME:key=value,... sets keys of the scene's "integrator" block (rr_depth, max_depth,
polarization, branches, ...) in a copy; every spp counts paths per pixel (Cycles' samples), so a variant
with integrator.branches = k renders spp / k camera samples of k paths each; `bin=DIR` runs that variant with another build's ochre and ochre-converge
(e.g. an export of an earlier commit, to compare before and after), else --ochre-bin. The scenes are written to OUT/scenes/ (paths made absolute); every variant is judged
against the reference of the scene's own settings (the levers compared this way must not change the
converged image). Output in OUT: results.csv (one row per renderer, variant and spp), summary.md (the table
of C), images in OUT/exr/. With --lock FILE every timed render runs under `flock FILE`.
"""
import argparse, csv, json, math, os, re, shutil, subprocess, sys
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..', '..'))
EPS = 1e-2
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # Rec.709 Y


# ---------------------------------------------------------------- metrics (tested by test_metrics.py)
def relmse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + EPS)))


def luminance_relmse(x, ref):
    return relmse(x @ LUMINANCE, ref @ LUMINANCE)


def reference_floor(a, b):
    """relMSE of the mean of two independent half references: E[(ref - truth)^2] = E[(a - b)^2] / 4."""
    ref = 0.5 * (a + b)
    return float(np.mean((a - b) ** 2 / 4 / (ref ** 2 + EPS)))


def figure_of_merit(rows, floor=0.0):
    """C = geometric mean over rows of (relMSE - floor) x seconds."""
    return math.exp(np.mean([math.log(max(r['relmse'] - floor, 1e-12) * r['seconds']) for r in rows]))


def loglog_fit(rows):
    """Least-squares line through (log seconds, log relMSE): (slope, intercept)."""
    slope, intercept = np.polyfit([math.log(r['seconds']) for r in rows], [math.log(r['relmse']) for r in rows], 1)
    return float(slope), float(intercept)


def loglog_slope(rows):
    return loglog_fit(rows)[0]


def relmse_at(rows, seconds):
    """(relMSE after `seconds` of rendering read off the log-log fit, extrapolated?); (None, True) when
    `seconds` lies more than a factor 4 outside the swept render times."""
    times = [r['seconds'] for r in rows]
    if seconds < min(times) / 4 or seconds > max(times) * 4:
        return None, True
    slope, intercept = loglog_fit(rows)
    return math.exp(intercept + slope * math.log(seconds)), not min(times) <= seconds <= max(times)


def read_exr(path):  # -> float64 array (height, width, 3): R, G, B
    tmp = path + '.rgb.exr'
    subprocess.run(['oiiotool', path, '--ch', 'R,G,B', '-d', 'float', '-o', tmp], check=True)
    out = subprocess.run(['oiiotool', '--dumpdata', tmp], capture_output=True, text=True, check=True).stdout
    os.remove(tmp)
    w, h, c = map(int, re.search(r':\s*(\d+) x\s*(\d+), (\d+) channel', out).groups())
    px = [ln.split(':', 1)[1].split() for ln in out.splitlines() if ln.lstrip().startswith('Pixel (')]
    return np.array(px, dtype=np.float64).reshape(h, w, c)


# ---------------------------------------------------------------- renderers
def locked(cmd, lock):
    return (['flock', lock] + cmd) if lock else cmd


class Cycles:
    name = 'cycles'

    def __init__(self, args, scene):
        self.args, self.scene = args, scene

    def render(self, spp, seed, exr):
        cmd = [self.args.blender, '-b', '--factory-startup', '--debug-cycles', '--python',
               os.path.join(HERE, 'make_and_render.py'), '--', '--scene', self.scene, '--spp', str(spp),
               '--seed', str(seed), '--threads', str(self.args.threads), '--out', exr]
        p = subprocess.run(locked(cmd, self.args.lock), capture_output=True, text=True)
        m = re.search(r'Render time \(without synchronization\): ([0-9.eE+-]+)', p.stdout + p.stderr)
        if p.returncode or not m or not os.path.exists(exr):
            sys.exit(f'Blender failed on {exr} (rc {p.returncode}):\n' + (p.stdout + p.stderr)[-4000:])
        return float(m.group(1))

    def exr(self, spp):
        return os.path.join(self.args.out, 'exr', f'cycles_spp{spp}.exr')

    def time_sweep(self, spps):  # one render of every spp -> {spp: seconds}; the images stay in OUT/exr
        return {spp: self.render(spp, 0, self.exr(spp)) for spp in spps}


class Ochre:
    name = 'ochre'

    def __init__(self, args, scene, label, ochre_bin):
        self.args, self.scene, self.label, self.dir = args, scene, label, ochre_bin
        self.bin = os.path.join(ochre_bin, 'ochre')
        # integrator.branches: each camera sample traces that many paths. Every spp here counts paths per
        # pixel, as Cycles' samples do, so a branched variant renders spp / branches camera samples.
        self.branches = int(json.load(open(scene)).get('integrator', {}).get('branches', 1))

    def camera_spp(self, spp):
        if spp % self.branches:
            sys.exit(f'ochre {self.label}: {spp} samples per pixel are not a multiple of its {self.branches} branches')
        return spp // self.branches

    def render(self, spp, seed, exr):
        cmd = [self.bin, 'render', self.scene, '-o', exr, '--spp', str(self.camera_spp(spp)), '--seed', str(seed),
               '--threads', str(self.args.threads), '-q']
        subprocess.run(locked(cmd, self.args.lock), check=True)

    def time_sweep(self, spps, ref_exr):  # one ochre-converge run -> {spp: seconds}; relMSE from our own reading
        csv_path = os.path.join(self.args.out, f'converge_{self.label}.csv')
        cmd = [os.path.join(self.dir, 'ochre-converge'), self.scene, '--reference', ref_exr,
               '--spp', ','.join(str(self.camera_spp(s)) for s in spps), '--threads', str(self.args.threads),
               '--csv', csv_path]
        subprocess.run(locked(cmd, self.args.lock), check=True, stdout=subprocess.DEVNULL)
        return {int(row['spp']) * self.branches: float(row['seconds']) for row in csv.DictReader(open(csv_path))}


def interleaved_best(sweeps, repeat):
    """sweeps: {key: function() -> {spp: seconds}}. Runs them in turn, `repeat` rounds (all keys once per
    round, so a machine whose speed drifts during the benchmark slows every renderer alike), and keeps each
    key's fastest time per spp -> {key: {spp: seconds}}."""
    best = {key: {} for key in sweeps}
    for _ in range(repeat):
        for key, sweep in sweeps.items():
            for spp, seconds in sweep().items():
                best[key][spp] = min(best[key].get(spp, math.inf), seconds)
    return best


def judged_rows(renderer, variant, spps, seconds, image_of, ref):
    """One results row per spp: the timed seconds and the relMSE of image_of(spp) (an EXR path) against ref."""
    rows = []
    for spp in spps:
        x = read_exr(image_of(spp))
        rows.append(dict(renderer=renderer, variant=variant, spp=spp, seconds=seconds[spp], relmse=relmse(x, ref),
                         luminance_relmse=luminance_relmse(x, ref)))
        name = renderer if variant == renderer else f'{renderer} {variant}'
        print(f"{name} spp {spp}: {seconds[spp]:.3f} s, relMSE {rows[-1]['relmse']:.4g}", flush=True)
    return rows


def variant_scene(args, spec):
    """Writes the scene of an ochre variant NAME:key=value,... (keys of the integrator block)."""
    name, _, rest = spec.partition(':')
    settings = dict(kv.split('=', 1) for kv in rest.split(',') if kv)
    ochre_bin = settings.pop('bin', args.ochre_bin)
    src = args.scene
    s = json.load(open(src))

    def absolute(o):  # "file" entries are relative to the scene's folder
        if isinstance(o, dict):
            return {k: (os.path.join(os.path.dirname(src), v) if k == 'file' and isinstance(v, str)
                        else absolute(v)) for k, v in o.items()}
        return [absolute(x) for x in o] if isinstance(o, list) else o
    s = absolute(s)
    for k, v in settings.items():
        s.setdefault('integrator', {})[k] = json.loads(v) if re.fullmatch(r'-?[0-9.]+|true|false', v) else v
    path = os.path.join(args.out, 'scenes', name + '.json')
    json.dump(s, open(path, 'w'), indent=1)
    return name, path, os.path.abspath(ochre_bin)


def reference_halves(args, tag):
    return [os.path.join(args.out, 'exr', f'ref_{tag}_{args.ref_spp // 2}spp_seed{seed}.exr') for seed in (1001, 1002)]


def reference(args, r, tag):
    halves = reference_halves(args, tag)
    for seed, exr in zip((1001, 1002), halves):
        if not (args.reuse_ref and os.path.exists(exr)):
            print(f'{tag}: reference half, {args.ref_spp // 2} spp, seed {seed}', flush=True)
            r.render(args.ref_spp // 2, seed, exr)
    a, b = (read_exr(h) for h in halves)
    ref_exr = os.path.join(args.out, 'exr', f'ref_{tag}.exr')
    subprocess.run(['oiiotool', halves[0], '--ch', 'R,G,B', halves[1], '--ch', 'R,G,B', '--add', '--mulc', '0.5',
                    '-d', 'float', '-o', ref_exr], check=True)
    return 0.5 * (a + b), reference_floor(a, b), ref_exr


def summarise(label, spps_rows, floor, pixels, colour_spp):
    rows = sorted(spps_rows, key=lambda r: r['spp'])
    at = next(r for r in rows if r['spp'] == colour_spp)
    return dict(label=label, C=figure_of_merit(rows), C_minus_floor=figure_of_merit(rows, floor),
                floor=floor, slope=loglog_slope(rows), at_1s=relmse_at(rows, 1.0), at_10s=relmse_at(rows, 10.0),
                samples_per_s=pixels * rows[-1]['spp'] / rows[-1]['seconds'],
                rgb_over_luminance=at['relmse'] / at['luminance_relmse'])


def checked_colour_spp(colour_spp, spps):
    """The sample count of the colour-noise column: one of the swept counts (checked before any render)."""
    if colour_spp is None:
        return sorted(spps)[len(spps) // 2]
    if colour_spp not in spps:
        sys.exit(f'--colour-spp {colour_spp} is not one of the swept sample counts {",".join(map(str, spps))}')
    return colour_spp


def summarise_results(args):
    """The summaries of an earlier run, from OUT/results.csv and its reference halves."""
    rows = [dict(r, spp=int(r['spp']), seconds=float(r['seconds']), relmse=float(r['relmse']),
                 luminance_relmse=float(r['luminance_relmse']))
            for r in csv.DictReader(open(os.path.join(args.out, 'results.csv')))]
    args.colour_spp = checked_colour_spp(args.colour_spp, sorted({r['spp'] for r in rows}))
    summaries = []
    for renderer in ('cycles', 'ochre'):
        mine = [r for r in rows if r['renderer'] == renderer]
        if not mine:
            continue
        a, b = (read_exr(h) for h in reference_halves(args, renderer))
        for variant in dict.fromkeys(r['variant'] for r in mine):
            label = 'Cycles' if renderer == 'cycles' else f'ochre {variant}'
            summaries.append(summarise(label, [r for r in mine if r['variant'] == variant], reference_floor(a, b),
                                       a.shape[0] * a.shape[1], args.colour_spp))
    return summaries


def summary_table(args, summaries):
    base = next((s['C'] for s in summaries if s['label'] == 'Cycles'), None)
    lines = [f'scene `{os.path.relpath(args.scene, ROOT)}`, spp {args.spps}, {args.threads} threads, '
             f'references {args.ref_spp} spp, best of {args.repeat}',
             '', '| renderer | C = relMSE x s | C, reference floor subtracted | C / C(Cycles) | samples/s '
             f'| relMSE at 1 s | relMSE at 10 s | log-log slope | RGB / luminance relMSE at {args.colour_spp} spp |',
             '|---|---|---|---|---|---|---|---|---|']

    def at(fit):
        value, extrapolated = fit
        return '-' if value is None else f"{value:.3g}{'*' if extrapolated else ''}"
    for s in summaries:
        ratio = f"{s['C'] / base:.2f}" if base else '-'
        lines.append(f"| {s['label']} | {s['C']:.4g} | {s['C_minus_floor']:.4g} | {ratio} | "
                     f"{s['samples_per_s'] / 1e6:.3f} M | {at(s['at_1s'])} | {at(s['at_10s'])} | {s['slope']:.2f} | "
                     f"{s['rgb_over_luminance']:.3f} |")
    return '\n'.join(lines) + '\n'


def write_summary(args, summaries):
    table = summary_table(args, summaries)
    open(os.path.join(args.out, 'summary.md'), 'w').write(table)
    print(table, end='')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--scene', default=os.path.join(ROOT, 'scenes/benchmark/cbox-matched.json'))
    ap.add_argument('--renderers', default='cycles,ochre')
    ap.add_argument('--variant', action='append', default=[], help='ochre variant NAME:key=value,...')
    ap.add_argument('--ref-spp', type=int, default=4096)
    ap.add_argument('--spps', default='8,16,32,64,128,256')
    ap.add_argument('--colour-spp', type=int, default=None,
                    help='sample count of the RGB / luminance column, one of --spps (default: the middle one)')
    ap.add_argument('--repeat', type=int, default=3)
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--reuse-ref', action='store_true', help='keep reference EXRs from an earlier run in OUT')
    ap.add_argument('--blender', default='blender')
    ap.add_argument('--ochre-bin', default=os.path.join(ROOT, 'build/bin'))
    ap.add_argument('--lock', default='', help='run every render under flock LOCK')
    ap.add_argument('--summarise', action='store_true',
                    help='only rewrite OUT/summary.md from OUT/results.csv and the reference halves')
    ap.add_argument('--out', required=True)
    args = ap.parse_args()
    args.scene = os.path.abspath(args.scene)
    if args.summarise:
        return write_summary(args, summarise_results(args))
    spps = [int(x) for x in args.spps.split(',')]
    args.colour_spp = checked_colour_spp(args.colour_spp, spps)
    for d in ('exr', 'scenes'):
        os.makedirs(os.path.join(args.out, d), exist_ok=True)
    renderers = args.renderers.split(',')
    if 'cycles' in renderers and not shutil.which(args.blender):
        sys.exit(f'{args.blender} not found: apt-get install -y --no-install-recommends blender (docs/performance.md)')

    # References first, then the timed sweeps of every renderer and variant in interleaved rounds.
    sweeps = {}
    if 'cycles' in renderers:
        cy = Cycles(args, args.scene)
        cycles_ref, cycles_floor, _ = reference(args, cy, 'cycles')
        sweeps['cycles'] = lambda: cy.time_sweep(spps)
    ochres = []
    if 'ochre' in renderers:
        _, ref_scene, _ = variant_scene(args, 'reference')
        ochre_ref, ochre_floor, ref_exr = reference(args, Ochre(args, ref_scene, 'ref', args.ochre_bin), 'ochre')
        for label, scene, ochre_bin in (variant_scene(args, v) for v in (args.variant or ['ochre'])):
            o = Ochre(args, scene, label, ochre_bin)
            ochres.append(o)
            sweeps[f'ochre {label}'] = lambda o=o: o.time_sweep(spps, ref_exr)
    best = interleaved_best(sweeps, args.repeat)

    def ochre_image(o, spp):  # the same image ochre-converge timed (same seed and settings)
        exr = os.path.join(args.out, 'exr', f'ochre_{o.label}_spp{spp}.exr')
        o.render(spp, 0, exr)
        return exr

    results, summaries = [], []
    if 'cycles' in renderers:
        rows = judged_rows('cycles', 'cycles', spps, best['cycles'], cy.exr, cycles_ref)
        summaries.append(summarise('Cycles', rows, cycles_floor, cycles_ref.shape[0] * cycles_ref.shape[1],
                                   args.colour_spp))
        results += rows
    for o in ochres:
        rows = judged_rows('ochre', o.label, spps, best[f'ochre {o.label}'], lambda spp, o=o: ochre_image(o, spp),
                           ochre_ref)
        summaries.append(summarise(f'ochre {o.label}', rows, ochre_floor, ochre_ref.shape[0] * ochre_ref.shape[1],
                                   args.colour_spp))
        results += rows

    with open(os.path.join(args.out, 'results.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        w.writeheader()
        w.writerows(results)
    write_summary(args, summaries)


if __name__ == '__main__':
    main()
