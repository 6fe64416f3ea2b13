"""Tests of the Cycles benchmark harness (tools/dev/cycles, docs/performance.md "Time to error against Cycles").

    python3 test_harness.py            the metrics and scene variants on synthetic data (numpy only)
    python3 test_harness.py --blender  one tiny Cycles render of scenes/benchmark/cbox-matched.json

Exit code 77 (ctest's skip) when numpy, or for --blender Blender or oiiotool, is missing: CI machines
have no Blender.
"""
import argparse, importlib.util, json, math, os, shutil, subprocess, sys, tempfile, unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
SKIP = 77

try:
    import numpy as np
except ImportError:
    print('numpy missing: skipped')
    sys.exit(SKIP)

spec = importlib.util.spec_from_file_location('run_benchmark', os.path.join(ROOT, 'tools/dev/cycles/run_benchmark.py'))
rb = importlib.util.module_from_spec(spec)
spec.loader.exec_module(rb)


class Metrics(unittest.TestCase):
    def test_relmse_is_the_epsilon_relative_squared_error(self):
        ref = np.full((4, 5, 3), 1.0)
        self.assertAlmostEqual(rb.relmse(ref + 0.1, ref), 0.01 / 1.01, places=12)
        ref[0, 0] = [0.0, 0.0, 0.0]  # a black pixel: the epsilon 1e-2 keeps it finite
        x = ref.copy()
        x[0, 0] = [0.1, 0.1, 0.1]
        self.assertAlmostEqual(rb.relmse(x, ref), 3 * (0.01 / 0.01) / 60, places=12)

    def test_luminance_relmse_ignores_an_error_of_constant_luminance(self):
        ref = np.full((2, 2, 3), 0.5)
        d = np.array([0.0722, 0.0, -0.2126]) * 0.1  # Rec.709 Y of d is 0
        self.assertAlmostEqual(rb.luminance_relmse(ref + d, ref), 0.0, places=14)
        self.assertGreater(rb.relmse(ref + d, ref), 0.0)

    def test_reference_floor_of_two_halves(self):
        ref = np.full((3, 3, 3), 2.0)
        d = 0.2
        self.assertAlmostEqual(rb.reference_floor(ref + d, ref - d), d * d / (4.0 + 1e-2), places=12)

    def test_figure_of_merit_of_a_one_over_t_convergence(self):
        rows = [dict(spp=s, seconds=0.01 * s, relmse=0.5 / (0.01 * s)) for s in (8, 16, 32, 64)]
        self.assertAlmostEqual(rb.figure_of_merit(rows), 0.5, places=12)
        self.assertAlmostEqual(rb.loglog_slope(rows), -1.0, places=9)
        floor = 1e-3
        lifted = [dict(r, relmse=r['relmse'] + floor) for r in rows]
        self.assertAlmostEqual(rb.figure_of_merit(lifted, floor), 0.5, places=9)
        self.assertGreater(rb.figure_of_merit(lifted), 0.5)

    def test_relmse_at_reads_the_log_log_fit(self):
        rows = [dict(spp=s, seconds=0.1 * s, relmse=0.02 * (0.1 * s) ** -1.2) for s in (8, 32, 128)]  # 0.8-12.8 s
        value, extrapolated = rb.relmse_at(rows, 1.0)
        self.assertAlmostEqual(value, 0.02, places=12)
        self.assertFalse(extrapolated)
        value, extrapolated = rb.relmse_at(rows, 40.0)  # beyond the sweep, within 4x: extrapolated along the fit
        self.assertAlmostEqual(value, 0.02 * 40.0 ** -1.2, places=12)
        self.assertTrue(extrapolated)
        self.assertEqual(rb.relmse_at(rows, 0.1), (None, True))  # 8x below the shortest render

    def test_seconds_to_a_target_relmse_reads_the_fit_with_the_floor_subtracted(self):
        floor = 2e-4
        rows = [dict(spp=s, seconds=0.5 * s, relmse=0.04 / (0.5 * s) + floor) for s in (16, 32, 64, 128)]  # 8-64 s
        seconds, extrapolated = rb.seconds_to(rows, 1e-3, floor)
        self.assertAlmostEqual(seconds, 40.0, places=9)  # 0.04 / t = 1e-3
        self.assertFalse(extrapolated)
        self.assertGreater(rb.seconds_to(rows, 1e-3)[0], 40.0)  # with the floor in, later
        self.assertTrue(rb.seconds_to(rows, 2e-4, floor)[1])  # 200 s: beyond the sweep, within 4x
        self.assertEqual(rb.seconds_to(rows, 1e-5, floor), (None, True))

    def test_monte_carlo_images_give_sigma_squared_times_seconds_per_sample(self):
        rng = np.random.default_rng(7)
        truth = rng.uniform(0.2, 2.0, (64, 64, 3))
        sigma, seconds_per_spp = 0.3, 0.02
        rows = []
        for spp in (8, 32, 128):
            x = truth + rng.normal(0.0, sigma / math.sqrt(spp), truth.shape)
            rows.append(dict(spp=spp, seconds=seconds_per_spp * spp, relmse=rb.relmse(x, truth)))
        expected = sigma ** 2 * seconds_per_spp * np.mean(1.0 / (truth ** 2 + 1e-2))
        self.assertAlmostEqual(rb.figure_of_merit(rows) / expected, 1.0, delta=0.03)


class Variants(unittest.TestCase):
    def test_variant_scene_sets_integrator_keys_and_makes_paths_absolute(self):
        with tempfile.TemporaryDirectory() as out:
            os.makedirs(os.path.join(out, 'scenes'))
            scene = os.path.join(ROOT, 'scenes/benchmark/cbox-matched.json')
            args = argparse.Namespace(scene=scene, out=out, ochre_bin='bin')
            name, path, _ = rb.variant_scene(args, 'late:rr_depth=7,polarization=off')
            self.assertEqual(name, 'late')
            s = json.load(open(path))
            self.assertEqual(s['integrator']['rr_depth'], 7)
            self.assertEqual(s['integrator']['polarization'], 'off')
            self.assertEqual(s['integrator']['max_depth'], 5)  # kept from the scene
            files = [sh['file'] for sh in s['shapes']]
            self.assertTrue(all(os.path.isabs(f) and os.path.exists(f) for f in files), files)
            name, path, _ = rb.variant_scene(args, 'plain')
            self.assertEqual(json.load(open(path))['integrator'], json.load(open(scene))['integrator'])

    def test_resolution_includes_and_the_reference_without_a_noise_threshold(self):
        with tempfile.TemporaryDirectory() as out:
            os.makedirs(os.path.join(out, 'scenes'))
            scene = os.path.join(ROOT, 'scenes/default/default.json')
            args = argparse.Namespace(scene=scene, out=out, ochre_bin='bin', resolution=rb.checked_resolution('32x18'))
            _, path, _ = rb.variant_scene(args, 'nt:noise_threshold=0.05')
            s = json.load(open(path))
            self.assertEqual(s['film']['resolution'], [32, 18])
            self.assertEqual(s['integrator']['noise_threshold'], 0.05)
            self.assertTrue(all(os.path.isabs(f) and os.path.exists(f) for f in s['include']), s['include'])
            ref = json.load(open(rb.variant_scene(args, 'reference')[1]))
            self.assertNotIn('noise_threshold', ref['integrator'])
            self.assertEqual(ref['film']['resolution'], [32, 18])
        self.assertIsNone(rb.checked_resolution(''))
        for bad in ('320', '320x0', 'x180', '320x180x2'):
            with self.assertRaises(SystemExit):
                rb.checked_resolution(bad)

    def test_adaptive_sweep_points_are_thresholds_at_the_most_samples(self):
        uniform = argparse.Namespace(noise_thresholds='', max_spp=512)
        self.assertEqual(rb.point_settings(uniform, 32), (32, 0.0))
        self.assertEqual(rb.point_name(uniform, 32), 'spp32')
        adaptive = argparse.Namespace(noise_thresholds='0.1,0.05', max_spp=512)
        self.assertEqual(rb.point_settings(adaptive, 0.05), (512, 0.05))
        self.assertEqual(rb.point_name(adaptive, 0.05), 'nt0.05_max512')
        rows = [dict(spp=512, noise_threshold=e, seconds=t, relmse=0.1 / t, luminance_relmse=0.05 / t)
                for e, t in ((0.1, 2.0), (0.05, 8.0), (0.025, 30.0))]
        s = rb.summarise('ochre', rows, 0.0, 100, 0.05, 1e-3)
        self.assertIsNone(s['samples_per_s'])  # not a fixed count per pixel
        self.assertAlmostEqual(s['rgb_over_luminance'], 2.0, places=12)
        self.assertAlmostEqual(s['C'], 0.1, places=12)

    def test_interleaved_rounds_alternate_renderers_and_keep_the_fastest_time(self):
        calls = []
        def sweep(key, times):  # a renderer whose k-th sweep takes times[k] seconds at every spp
            def run():
                calls.append(key)
                return {8: times[calls.count(key) - 1], 32: 4 * times[calls.count(key) - 1]}
            return run
        best = rb.interleaved_best({'cycles': sweep('cycles', [3.0, 2.0, 2.5]),
                                    'ochre a': sweep('ochre a', [1.0, 1.5, 0.5])}, 3)
        self.assertEqual(calls, ['cycles', 'ochre a'] * 3)  # rounds, not one renderer's repeats in a row
        self.assertEqual(best, {'cycles': {8: 2.0, 32: 8.0}, 'ochre a': {8: 0.5, 32: 2.0}})

    def test_branched_variants_count_paths_per_pixel(self):
        with tempfile.TemporaryDirectory() as out:
            os.makedirs(os.path.join(out, 'scenes'))
            scene = os.path.join(ROOT, 'scenes/benchmark/cbox-matched.json')
            args = argparse.Namespace(scene=scene, out=out, ochre_bin='bin')
            _, path, _ = rb.variant_scene(args, 'b4:branches=4')
            o = rb.Ochre(args, path, 'b4', 'bin')
            self.assertEqual(o.branches, 4)
            self.assertEqual(o.camera_spp(32), 8)  # 32 paths per pixel: 8 camera samples of 4 paths
            with self.assertRaises(SystemExit):
                o.camera_spp(6)

    def test_colour_spp_is_a_swept_count_checked_before_rendering(self):
        self.assertEqual(rb.checked_colour_spp(None, [8, 32, 128]), 32)  # the middle of the sweep
        self.assertEqual(rb.checked_colour_spp(None, [4, 8, 16, 32, 64]), 16)
        self.assertEqual(rb.checked_colour_spp(128, [8, 32, 128]), 128)
        with self.assertRaises(SystemExit) as e:
            rb.checked_colour_spp(64, [8, 32, 128])
        self.assertIn('--colour-spp 64', str(e.exception.code))
        with tempfile.TemporaryDirectory() as out:  # the whole tool stops before it writes anything
            r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools/dev/cycles/run_benchmark.py'), '--out',
                                os.path.join(out, 'bench'), '--renderers', 'ochre', '--spps', '8,32',
                                '--colour-spp', '64'], capture_output=True, text=True)
            self.assertNotEqual(r.returncode, 0)
            self.assertIn('not one of the swept sample counts 8,32', r.stderr)
            self.assertFalse(os.path.exists(os.path.join(out, 'bench')))


def blender_render(ochre_bin):
    if not shutil.which('blender') or not shutil.which('oiiotool'):
        print('blender or oiiotool missing: skipped (apt-get install -y --no-install-recommends blender)')
        return SKIP
    with tempfile.TemporaryDirectory() as out:
        exr = os.path.join(out, 'c.exr')
        args = argparse.Namespace(blender='blender', threads=1, lock='', repeat=1, ochre_bin=ochre_bin)
        seconds = rb.Cycles(args, os.path.join(ROOT, 'scenes/benchmark/cbox-matched.json')).render(1, 0, exr)
        img = rb.read_exr(exr)
        meta = json.load(open(exr[:-4] + '.json'))
        ok = img.shape == (256, 256, 3) and seconds > 0 and meta['cycles_max_bounces'] == 4 and img.mean() > 0.01
        print(f'Cycles render {seconds:.3f} s, shape {img.shape}, mean {img.mean():.4f}, meta {meta["cycles_max_bounces"]}')
        # The cave pair: the chamber's procedural displacement comes through `ochre export-mesh` (the triangles
        # ochre renders), the torch as a point light; a small film and one sample (the 307 k triangles dominate).
        pair = json.load(open(os.path.join(ROOT, 'scenes/benchmark/cave-lambert.json')))
        pair['film']['resolution'] = [32, 18]
        pair['shapes'][0]['file'] = os.path.join(ROOT, 'scenes/default/cave.obj')
        scene = os.path.join(out, 'cave-lambert.json')
        json.dump(pair, open(scene, 'w'))
        exr = os.path.join(out, 'cave.exr')
        rb.Cycles(args, scene).render(1, 0, exr)
        cave, meta = rb.read_exr(exr), json.load(open(exr[:-4] + '.json'))
        cached = os.path.exists(os.path.join(out, 'cave-lambert.json.cave.ply'))
        print(f'cave pair: {meta["triangles"]} triangles, shape {cave.shape}, mean {cave.mean(axis=(0, 1))}, '
              f'mesh cached {cached}')
        ok = ok and meta['triangles'] == 307200 and cave.shape == (18, 32, 3) and cave[..., 0].mean() > 0.05 and cached
        return 0 if ok else 1


if __name__ == '__main__':
    if '--blender' in sys.argv:
        sys.exit(blender_render(sys.argv[sys.argv.index('--blender') + 1]))
    unittest.main()
