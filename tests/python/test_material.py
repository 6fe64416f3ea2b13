"""ochre.material (docs/python.md): eval, mueller, sample and albedo over numpy arrays, and bad input named
as in a scene."""

import math
import os
import subprocess
import time
import unittest

import numpy as np

import ochre


def direction(theta_deg, phi_deg=0.0):
    t, p = math.radians(theta_deg), math.radians(phi_deg)
    return np.array([math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)])


class Lambert(unittest.TestCase):
    def setUp(self):
        self.m = ochre.material({"type": "lambert", "color": 0.8})

    def test_eval_is_albedo_over_pi_above_and_zero_below(self):
        wi = np.array([direction(10), direction(60, 90), direction(120)])
        f = self.m.eval(wi, direction(30), 550)
        np.testing.assert_allclose(f[:2], 0.8 / math.pi, rtol=1e-6)
        self.assertEqual(f[2], 0.0)

    def test_arrays_broadcast(self):
        wi = np.stack([direction(t) for t in (0, 20, 40)])[:, None, :]  # (3, 1, 3)
        wo = np.stack([direction(t, 45) for t in (5, 15)])              # (2, 3)
        lam = np.array([450.0, 650.0])                                   # (2,)
        self.assertEqual(self.m.eval(wi, wo, lam).shape, (3, 2))
        self.assertEqual(self.m.eval(direction(0), direction(0)).shape, ())
        self.assertEqual(self.m.mueller(wi, wo, lam)["matrix"].shape, (3, 2, 4, 4))

    def test_directions_need_not_be_unit_length(self):
        self.assertAlmostEqual(float(self.m.eval([0, 0, 5], [0, 3, 3])), 0.8 / math.pi, places=6)

    def test_albedo_both_ways(self):
        a = self.m.albedo([0, 45, 80], samples=20000)
        np.testing.assert_allclose(a["mc_albedo"], 0.8, rtol=1e-6)
        np.testing.assert_allclose(a["quadrature_albedo"], 0.8, rtol=1e-4)

    def test_samples_are_cosine_distributed(self):
        s = self.m.sample(np.broadcast_to(direction(30), (20000, 3)), 550, seed=3)
        self.assertTrue(s["valid"].all())
        self.assertFalse(s["delta"].any())
        cos = s["wi"][:, 2]
        self.assertTrue((cos > 0).all())
        self.assertAlmostEqual(float(cos.mean()), 2 / 3, delta=0.01)  # E[cos] of a cosine density
        np.testing.assert_allclose(s["pdf"], cos / math.pi, rtol=1e-5)
        np.testing.assert_allclose(s["weight"], 0.8, rtol=1e-5)
        # Given random numbers give the same sample.
        u = np.array([[0.5, 0.25, 0.75]])
        self.assertTrue(np.array_equal(self.m.sample(direction(30), u=u)["wi"], self.m.sample(direction(30), u=u)["wi"]))

    def test_not_polarizing(self):
        self.assertFalse(self.m.polarizes())
        mm = self.m.mueller(direction(20), direction(50))["matrix"]
        self.assertAlmostEqual(float(mm[0, 0]), 0.8 / math.pi, places=6)
        self.assertTrue(np.all(mm.reshape(16)[1:] == 0))  # an ideal depolarizer


class Conductor(unittest.TestCase):
    def test_rough_gold_polarizes_and_m00_is_eval(self):
        m = ochre.material({"type": "conductor", "metal": "Au", "roughness": 0.3})
        self.assertTrue(m.polarizes())
        wi, wo = direction(60), direction(60, 180)  # the mirror configuration
        r = m.mueller(wi, wo, [450, 650])
        np.testing.assert_allclose(r["matrix"][:, 0, 0], m.eval(wi, wo, [450, 650]), rtol=1e-6)
        self.assertGreater(abs(float(r["matrix"][0, 0, 1])), 1e-4)  # s and p reflect differently at 60 degrees
        self.assertGreater(float(m.eval(wi, wo, 650)), float(m.eval(wi, wo, 450)))  # gold is yellow
        self.assertEqual(r["in_x"].shape, (2, 3))


class Interrupt(unittest.TestCase):
    def test_ctrl_c_stops_a_long_albedo(self):
        # 2^40 samples: hours of work; SIGINT after 0.3 s must end it in about a second (docs/python.md). The
        # evaluation holds the GIL, so the signal comes from another process, as from a terminal.
        m = ochre.material({"type": "lambert", "color": 0.8})
        killer = subprocess.Popen(["sh", "-c", f"sleep 0.3; kill -INT {os.getpid()}"])
        start = time.monotonic()
        with self.assertRaises(KeyboardInterrupt):
            m.albedo([30], samples=2**40)
        killer.wait()
        self.assertLess(time.monotonic() - start, 5.0)
        self.assertAlmostEqual(float(m.albedo([30], samples=1000)["mc_albedo"][0]), 0.8, places=5)


class BadInput(unittest.TestCase):
    def test_unknown_parameter_names_the_material_and_parameter(self):
        with self.assertRaises(ochre.InputError) as error:
            ochre.material({"type": "lambert", "colour": 0.5}, name="paint")
        self.assertIn("material 'paint'", str(error.exception))
        self.assertIn("colour", str(error.exception))

    def test_zero_direction_and_wavelength_out_of_range(self):
        m = ochre.material({"type": "lambert"})
        with self.assertRaises(ochre.InputError) as error:
            m.eval([[0, 0, 1], [0, 0, 0]], [0, 0, 1])
        self.assertIn("wi[1]: a direction must be a non-zero finite vector", str(error.exception))
        with self.assertRaises(ochre.InputError) as error:
            m.eval([0, 0, 1], [0, 0, 1], 900)
        self.assertIn("900 nm is outside", str(error.exception))
        with self.assertRaises(ValueError):
            m.eval([0, 1], [0, 0, 1])

    def test_material_file_with_a_name(self):
        path = os.path.join(os.environ["OCHRE_SOURCE_DIR"], "scenes/cornell-box/cornell-box.json")
        red = ochre.material(path, name="red")
        self.assertGreater(float(red.eval(direction(0), direction(0), 650)), float(red.eval(direction(0), direction(0), 450)))


if __name__ == "__main__":
    unittest.main()
