#!/usr/bin/env python3
"""Checks of chute_fits.py: every fit recovers the parameters of synthetic data generated from
known parameters (Weinhart et al. 2012, Tables 1-2 and Eqs. 52-53) with Gaussian noise, to
within four of its own standard errors, and the friction law (Eq. 37) returns tan(theta)
exactly on the flow rule (Eq. 36) it was derived from. Deterministic (fixed seed)."""
import unittest

import numpy as np

from talus.studies import chute_fits as cf

HS = {"A": 3.355, "delta1": 17.708, "delta2": 32.780}  # Table 1, lambda = 1


class ChuteFits(unittest.TestCase):
    def setUp(self):
        self.rng = np.random.default_rng(2012)

    def assertRecovers(self, truth, params, se, k=4.0):
        for name, value in truth.items():
            self.assertTrue(np.isfinite(se[name]) and se[name] > 0, name)
            self.assertLess(abs(params[name] - value), k * se[name], "%s: %g vs %g ± %g" % (name, params[name], value, se[name]))

    def test_err_is_eq49(self):
        self.assertAlmostEqual(cf.err([3, 4]), 5.0)  # sqrt((9 + 16) / 1)

    def test_hstop35_horizontal_fit(self):
        h = np.linspace(3, 40, 30)
        theta = cf.theta_stop35(h, **HS) + self.rng.normal(0, 0.15, h.size)  # intervals of 0.5 deg
        p, se, e = cf.fit_hstop35(h, theta)
        self.assertRecovers(HS, p, se)
        self.assertLess(abs(e - 0.15), 0.05)
        np.testing.assert_allclose(cf.hstop35(cf.theta_stop35(h, **HS), **HS), h, rtol=1e-10)

    def test_hstop38_vertical_fit(self):
        truth = {"A": 6.0, "delta1": 19.0, "delta2": 30.0}
        theta = np.linspace(19.6, 29.5, 25)
        h = cf.hstop38(theta, **truth) + self.rng.normal(0, 0.3, theta.size)
        p, se, _ = cf.fit_hstop38(theta, h)
        self.assertRecovers(truth, p, se)

    def test_flow_rule_and_friction_law(self):
        theta = self.rng.uniform(21, 29, 40)
        h = cf.hstop35(theta, **HS) * self.rng.uniform(1.2, 8, theta.size)
        F = 0.196 * h / cf.hstop35(theta, **HS) - 0.040
        p, se, _ = cf.fit_flow_rule(h, theta, F + self.rng.normal(0, 0.02, h.size), HS)
        self.assertRecovers({"beta": 0.196, "gamma": 0.040}, p, se)
        # Eq. (37) inverts Eqs. (35)-(36): on the exact flow rule mu = tan(theta).
        np.testing.assert_allclose(cf.friction_law(h, F, HS, 0.196, 0.040), np.tan(np.radians(theta)), rtol=1e-12)

    def test_bulk_density_eq52(self):
        truth = {"c0": 0.5985, "c1": 4.8, "c2": 40.85}
        theta = np.repeat(np.arange(20.0, 31.0, 1.0), 3)
        phi = cf.density52(theta, **truth) + self.rng.normal(0, 0.002, theta.size)
        p, se, e = cf.fit_density(theta, phi)
        self.assertRecovers(truth, p, se)
        self.assertLess(e, 0.003)

    def test_stress_ratio_eq53(self):
        truth = {"d0": 132.0, "d1": 21.5}
        theta = np.repeat(np.arange(20.0, 31.0, 1.0), 3)
        K = cf.stress_ratio53(theta, **truth) + self.rng.normal(0, 0.005, theta.size)
        p, se, _ = cf.fit_stress_ratio(theta, K)
        self.assertRecovers(truth, p, se)

    def test_arrest_intervals_of_a_partial_staircase(self):
        # A staircase cut off part-way: each interval brackets the threshold that decided its cases.
        rows = []
        for H, angles in ((4, [21, 22, 23, 24, 25, 26, 25.5]), (6, [25.5, 25, 24.5])):
            for th in angles:
                h = H - 0.2
                rows.append({"lambda": 1.0, "H": H, "angle": th, "h": h,
                             "arrested": float(h < cf.hstop35(th, **HS))})
        iv = cf.arrest_intervals(rows)
        angle = [r for r in iv if r["kind"] == "angle"]
        self.assertEqual([r["H"] for r in angle], [4])  # H = 6 has not arrested yet: no interval
        self.assertEqual((angle[0]["angle_lo"], angle[0]["angle_hi"]), (25.0, 25.5))
        self.assertTrue(25.0 <= cf.theta_stop35(3.8, **HS) <= 25.5)
        heights = {r["angle_lo"]: (r["h_lo"], r["h_hi"]) for r in iv if r["kind"] == "height"}
        self.assertEqual(heights, {25.0: (3.8, 5.8)})

    def test_fit_all_skips_a_flow_thinner_than_its_base_layer(self):
        # Eq. (54) has no profile when b_lambda >= h; the other fits still come out.
        runs = [{"lambda": 1.0, "flow_state": "steady", "h": h, "angle": th, "froude": f, "alpha": 1.3, "K": 1.05}
                for h, th, f in ((4.2, 25.5, 0.07), (5.9, 24.5, 0.1), (5.8, 23.5, 0.06))]
        iv = [{"lambda": 1.0, "kind": "angle", "h": h, "angle_lo": t - 0.25, "angle_hi": t + 0.25}
              for h in (4.0, 8.0, 16.0, 32.0) for t in [float(cf.theta_stop35(h, **HS))]]
        out = cf.fit_all(iv, runs, 1.0)
        self.assertIn("hstop35", out)
        self.assertIn("flow_rule", out)
        self.assertIn("stress_ratio", out)

    def test_shape_factor_eq54(self):
        theta = np.repeat([22.0, 24.0, 26.0, 28.0], 4)
        h = np.tile([10.0, 18.0, 27.0, 36.0], 4)
        alpha = cf.shape_factor54(h, theta, 6.678, HS) + self.rng.normal(0, 0.005, h.size)
        p, se, _ = cf.fit_shape_factor(h, theta, alpha, HS)
        self.assertRecovers({"d_lambda": 6.678}, p, se)

    def test_shape_factor_of_bagnold_profile(self):
        # No base layer, no surface layer: the Bagnold profile of Eq. (54a), alpha = 5/4.
        hs = {"A": 1e-9, "delta1": 17.708, "delta2": 32.780}
        self.assertAlmostEqual(cf.shape_factor54([1e4], [24.0], 0.0, hs, n=200001)[0], 1.25, places=3)
        self.assertAlmostEqual(cf.shape_factor55(0), 1.0)


if __name__ == "__main__":
    unittest.main()
