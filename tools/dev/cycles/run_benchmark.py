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
"seconds to relMSE T" (--target-relmse, default 1e-3) is read off the log-log fit with the floor subtracted;
the column after it divides it by the first ochre variant's (e.g. --variant before:bin=... first).

--resolution WxH renders every image (references included) at that film size. --noise-thresholds E1,E2,...
sweeps adaptive sampling instead of sample counts: every render takes at most --max-spp samples per pixel
and stops each pixel at the threshold (ochre's --noise-threshold, Cycles' adaptive sampling with that
threshold and its automatic minimum); the references stay uniform. Compare it with a uniform sweep of the
same scene in another OUT: C is comparable across the two.

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


def seconds_to(rows, target, floor=0.0):
    """Render seconds at which the least-squares line through (log seconds, log(relMSE - floor)) reaches
    relMSE - floor = target (extrapolated?); (None, True) when that lies more than a factor 4 outside the
    swept render times."""
    slope, intercept = loglog_fit([dict(r, relmse=max(r['relmse'] - floor, 1e-12)) for r in rows])
    seconds = math.exp((math.log(target) - intercept) / slope)
    times = [r['seconds'] for r in rows]
    if seconds < min(times) / 4 or seconds > max(times) * 4:
        return None, True
    return seconds, not min(times) <= seconds <= max(times)


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

    def render(self, spp, seed, exr, threshold=0.0):
        cmd = [self.args.blender, '-b', '--factory-startup', '--debug-cycles', '--python',
               os.path.join(HERE, 'make_and_render.py'), '--', '--scene', self.scene, '--spp', str(spp),
               '--seed', str(seed), '--threads', str(self.args.threads), '--out', exr,
               '--ochre', os.path.join(getattr(self.args, 'ochre_bin', os.path.join(ROOT, 'build/bin')), 'ochre')]
        if threshold:
            cmd += ['--adaptive-threshold', repr(threshold)]
        p = subprocess.run(locked(cmd, self.args.lock), capture_output=True, text=True)
        m = re.search(r'Render time \(without synchronization\): ([0-9.eE+-]+)', p.stdout + p.stderr)
        if p.returncode or not m or not os.path.exists(exr):
            sys.exit(f'Blender failed on {exr} (rc {p.returncode}):\n' + (p.stdout + p.stderr)[-4000:])
        return float(m.group(1))

    def exr(self, point):
        return os.path.join(self.args.out, 'exr', f'cycles_{point_name(self.args, point)}.exr')

    def time_sweep(self, points):  # one render of every point -> {point: seconds}; the images stay in OUT/exr
        times = {}
        for p in points:
            spp, threshold = point_settings(self.args, p)
            times[p] = self.render(spp, 0, self.exr(p), threshold)
        return times


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

    def render(self, spp, seed, exr, threshold=0.0):
        cmd = [self.bin, 'render', self.scene, '-o', exr, '--spp', str(self.camera_spp(spp)), '--seed', str(seed),
               '--threads', str(self.args.threads), '-q']
        if threshold:
            cmd += ['--noise-threshold', repr(threshold)]
        subprocess.run(locked(cmd, self.args.lock), check=True)

    def time_sweep(self, points, ref_exr):  # one ochre-converge run -> {point: seconds}; relMSE from our own reading
        csv_path = os.path.join(self.args.out, f'converge_{self.label}.csv')
        cmd = [os.path.join(self.dir, 'ochre-converge'), self.scene, '--reference', ref_exr,
               '--threads', str(self.args.threads), '--csv', csv_path]
        if not self.args.noise_thresholds:
            cmd += ['--spp', ','.join(str(self.camera_spp(s)) for s in points)]
            subprocess.run(locked(cmd, self.args.lock), check=True, stdout=subprocess.DEVNULL)
            return {int(row['spp']) * self.branches: float(row['seconds']) for row in csv.DictReader(open(csv_path))}
        # Adaptive: one ochre-converge variant per threshold, each at the most samples a pixel may take.
        cmd += ['--spp', str(self.camera_spp(self.args.max_spp))]
        for i, threshold in enumerate(points):
            cmd += ['--variant', f't{i}:noise_threshold={threshold!r}']
        subprocess.run(locked(cmd, self.args.lock), check=True, stdout=subprocess.DEVNULL)
        return {points[int(row['variant'][1:])]: float(row['seconds']) for row in csv.DictReader(open(csv_path))}


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


def point_settings(args, point):
    """(samples per pixel, noise threshold) of a sweep point: a sample count, or with --noise-thresholds a
    threshold with --max-spp samples at most."""
    return (args.max_spp, point) if getattr(args, 'noise_thresholds', None) else (point, 0.0)


def point_name(args, point):
    spp, threshold = point_settings(args, point)
    return f'nt{threshold:g}_max{spp}' if threshold else f'spp{spp}'


def judged_rows(args, renderer, variant, points, seconds, image_of, ref):
    """One results row per sweep point: the timed seconds and the relMSE of image_of(point) (an EXR path)
    against ref."""
    rows = []
    for point in points:
        x = read_exr(image_of(point))
        spp, threshold = point_settings(args, point)
        rows.append(dict(renderer=renderer, variant=variant, spp=spp, noise_threshold=threshold,
                         seconds=seconds[point], relmse=relmse(x, ref), luminance_relmse=luminance_relmse(x, ref)))
        name = renderer if variant == renderer else f'{renderer} {variant}'
        print(f"{name} {point_name(args, point)}: {seconds[point]:.3f} s, relMSE {rows[-1]['relmse']:.4g}", flush=True)
    return rows


def variant_scene(args, spec):
    """Writes the scene of an ochre variant NAME:key=value,... (keys of the integrator block)."""
    name, _, rest = spec.partition(':')
    settings = dict(kv.split('=', 1) for kv in rest.split(',') if kv)
    ochre_bin = settings.pop('bin', args.ochre_bin)
    src = args.scene
    s = json.load(open(src))

    def here(v):
        return os.path.join(os.path.dirname(src), v)

    def absolute(o):  # "file" entries and includes are relative to the scene's folder
        if isinstance(o, dict):
            return {k: (here(v) if k == 'file' and isinstance(v, str) else
                        [here(x) for x in v] if k == 'include' else absolute(v)) for k, v in o.items()}
        return [absolute(x) for x in o] if isinstance(o, list) else o
    s = absolute(s)
    if getattr(args, 'resolution', None):
        s.setdefault('film', {})['resolution'] = args.resolution
    if name == 'reference':  # references take every sample in every pixel
        s.get('integrator', {}).pop('noise_threshold', None)
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


def summarise(label, spps_rows, floor, pixels, colour_spp, target):
    """The summary of one renderer's sweep; colour_spp: the sample count (uniform sweeps) or the noise
    threshold (adaptive sweeps) of the colour-noise column."""
    rows = sorted(spps_rows, key=lambda r: r['seconds'])
    at = next(r for r in rows if (r.get('noise_threshold') or r['spp']) == colour_spp)
    adaptive = any(r.get('noise_threshold') for r in rows)
    return dict(label=label, C=figure_of_merit(rows), C_minus_floor=figure_of_merit(rows, floor),
                to_target=seconds_to(rows, target, floor),
                floor=floor, slope=loglog_slope(rows), at_1s=relmse_at(rows, 1.0), at_10s=relmse_at(rows, 10.0),
                samples_per_s=None if adaptive else pixels * rows[-1]['spp'] / rows[-1]['seconds'],
                rgb_over_luminance=at['relmse'] / at['luminance_relmse'])


def checked_colour_spp(colour_spp, spps):
    """The sample count of the colour-noise column: one of the swept counts (checked before any render)."""
    if colour_spp is None:
        return sorted(spps)[len(spps) // 2]
    if colour_spp not in spps:
        sys.exit(f'--colour-spp {colour_spp} is not one of the swept sample counts {",".join(map(str, spps))}')
    return colour_spp


def checked_resolution(text):
    """--resolution WxH -> [W, H] (None when not given), checked before any render."""
    if not text:
        return None
    m = re.fullmatch(r'([1-9][0-9]*)x([1-9][0-9]*)', text)
    if not m:
        sys.exit(f'--resolution {text}: expected WxH, e.g. 320x180')
    return [int(m.group(1)), int(m.group(2))]


def summarise_results(args):
    """The summaries of an earlier run, from OUT/results.csv and its reference halves."""
    rows = [dict(r, spp=int(r['spp']), noise_threshold=float(r.get('noise_threshold') or 0.0),
                 seconds=float(r['seconds']), relmse=float(r['relmse']), luminance_relmse=float(r['luminance_relmse']))
            for r in csv.DictReader(open(os.path.join(args.out, 'results.csv')))]
    args.colour_spp = checked_colour_spp(args.colour_spp, sorted({r['noise_threshold'] or r['spp'] for r in rows}))
    summaries = []
    for renderer in ('cycles', 'ochre'):
        mine = [r for r in rows if r['renderer'] == renderer]
        if not mine:
            continue
        a, b = (read_exr(h) for h in reference_halves(args, renderer))
        for variant in dict.fromkeys(r['variant'] for r in mine):
            label = 'Cycles' if renderer == 'cycles' else f'ochre {variant}'
            summaries.append(summarise(label, [r for r in mine if r['variant'] == variant], reference_floor(a, b),
                                       a.shape[0] * a.shape[1], args.colour_spp, args.target_relmse))
    return summaries


def summary_table(args, summaries):
    base = next((s['C'] for s in summaries if s['label'] == 'Cycles'), None)
    swept = (f'noise thresholds {args.noise_thresholds} at most {args.max_spp} spp' if args.noise_thresholds
             else f'spp {args.spps}')
    lines = [f'scene `{os.path.relpath(args.scene, ROOT)}`, {swept}, {args.threads} threads, '
             f'references {args.ref_spp} spp, best of {args.repeat}',
             '', '| renderer | C = relMSE x s | C, reference floor subtracted | C / C(Cycles) | samples/s '
             f'| relMSE at 1 s | relMSE at 10 s | log-log slope | RGB / luminance relMSE at '
             f'{args.colour_spp}{" threshold" if args.noise_thresholds else " spp"} '
             f'| seconds to relMSE {args.target_relmse:g} | that / first ochre\'s |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    first = next((s['to_target'][0] for s in summaries if s['label'].startswith('ochre')), None)

    def million(value):
        return f'{value / 1e6:.3f} M' if value else '-'

    def share(value, of):
        return f'{value / of:.3f}' if value and of else '-'

    def at(fit):
        value, extrapolated = fit
        return '-' if value is None else f"{value:.3g}{'*' if extrapolated else ''}"
    for s in summaries:
        ratio = f"{s['C'] / base:.2f}" if base else '-'
        lines.append(f"| {s['label']} | {s['C']:.4g} | {s['C_minus_floor']:.4g} | {ratio} | "
                     f"{million(s['samples_per_s'])} | {at(s['at_1s'])} | {at(s['at_10s'])} | {s['slope']:.2f} | "
                     f"{s['rgb_over_luminance']:.3f} | {at(s['to_target'])} | {share(s['to_target'][0], first)} |")
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
    ap.add_argument('--colour-spp', type=lambda v: int(v) if v.isdigit() else float(v), default=None,
                    help='sample count (or noise threshold) of the RGB / luminance column, one of the sweep (default: the middle one)')
    ap.add_argument('--noise-thresholds', default='',
                    help='adaptive sweep: noise thresholds E1,E2,... (ochre --noise-threshold, Cycles\' adaptive '
                         'threshold), each with at most --max-spp samples per pixel, instead of --spps')
    ap.add_argument('--max-spp', type=int, default=1024, help='the most samples a pixel takes in an adaptive sweep')
    ap.add_argument('--repeat', type=int, default=3)
    ap.add_argument('--resolution', default='', help='film resolution WxH of every render (default: the scene\'s)')
    ap.add_argument('--target-relmse', type=float, default=1e-3,
                    help='the relMSE of the "seconds to" column (read off the log-log fit, floor subtracted)')
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
    args.resolution = checked_resolution(args.resolution)
    if args.summarise:
        return write_summary(args, summarise_results(args))
    spps = ([float(x) for x in args.noise_thresholds.split(',')] if args.noise_thresholds
            else [int(x) for x in args.spps.split(',')])  # the sweep points
    args.colour_spp = checked_colour_spp(args.colour_spp, spps)
    for d in ('exr', 'scenes'):
        os.makedirs(os.path.join(args.out, d), exist_ok=True)
    renderers = args.renderers.split(',')
    if 'cycles' in renderers and not shutil.which(args.blender):
        sys.exit(f'{args.blender} not found: apt-get install -y --no-install-recommends blender (docs/performance.md)')

    # References first, then the timed sweeps of every renderer and variant in interleaved rounds.
    sweeps = {}
    _, ref_scene, _ = variant_scene(args, 'reference')
    if 'cycles' in renderers:
        cy = Cycles(args, ref_scene if args.resolution else args.scene)
        cycles_ref, cycles_floor, _ = reference(args, cy, 'cycles')
        sweeps['cycles'] = lambda: cy.time_sweep(spps)
    ochres = []
    if 'ochre' in renderers:
        ochre_ref, ochre_floor, ref_exr = reference(args, Ochre(args, ref_scene, 'ref', args.ochre_bin), 'ochre')
        for label, scene, ochre_bin in (variant_scene(args, v) for v in (args.variant or ['ochre'])):
            o = Ochre(args, scene, label, ochre_bin)
            ochres.append(o)
            sweeps[f'ochre {label}'] = lambda o=o: o.time_sweep(spps, ref_exr)
    best = interleaved_best(sweeps, args.repeat)

    def ochre_image(o, point):  # the same image ochre-converge timed (same seed and settings)
        exr = os.path.join(args.out, 'exr', f'ochre_{o.label}_{point_name(args, point)}.exr')
        spp, threshold = point_settings(args, point)
        o.render(spp, 0, exr, threshold)
        return exr

    results, summaries = [], []
    if 'cycles' in renderers:
        rows = judged_rows(args, 'cycles', 'cycles', spps, best['cycles'], cy.exr, cycles_ref)
        summaries.append(summarise('Cycles', rows, cycles_floor, cycles_ref.shape[0] * cycles_ref.shape[1],
                                   args.colour_spp, args.target_relmse))
        results += rows
    for o in ochres:
        rows = judged_rows(args, 'ochre', o.label, spps, best[f'ochre {o.label}'], lambda spp, o=o: ochre_image(o, spp),
                           ochre_ref)
        summaries.append(summarise(f'ochre {o.label}', rows, ochre_floor, ochre_ref.shape[0] * ochre_ref.shape[1],
                                   args.colour_spp, args.target_relmse))
        results += rows

    with open(os.path.join(args.out, 'results.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        w.writeheader()
        w.writerows(results)
    write_summary(args, summaries)


if __name__ == '__main__':
    main()
