#!/usr/bin/python3
"""optiland as a peer for lenslab issue 37: Monte Carlo tolerancing of the Cooke triplet.

    PYTHONPATH=/work/peers/optiland /usr/bin/python3 bench/peer/optiland/cooke_tolerance.py

optiland.tolerancing (Tolerancing + MonteCarlo) on the NOMINAL CookeTriplet:

  operands      the issue-37 merit's four: polychromatic RMS spot radius at 0, 14
                and 20 deg (rms_spot_size, wavelength='all', hexapolar 5 rings,
                target 0) and EFL (f2, target 50), weight 1 each
  perturbations uniform within +-tol (optiland perturbations SET a value, so
                each sampler is centred on the nominal value):
                  radius     R * (1 +- 0.001), surfaces 1-6
                  thickness  t +- 0.02 mm, surfaces 1-5 (surface 6's thickness
                             is the compensator)
                  decenter   +-0.01 mm, x and y, surfaces 1-6 (optiland moves the
                             one surface; the following surfaces stay put)
                  tilt       +-0.01 deg (optiland's tilt is in radians:
                             +-1.745e-4 rad), about x and y, surfaces 1-6
                  index      +-5e-4 per glass (surfaces 1, 3, 5), only with
                             --index: optiland's own 'index' variable replaces
                             the glass by a NON-dispersive IdealMaterial (absolute
                             n), so it cannot offset a catalog glass; this script
                             wraps each glass in OffsetGlass (n_glass(lambda)+dn)
                             and drives it with an object that has the interface
                             MonteCarlo uses (apply/reset/value/variable).
  compensator   back focus (thickness of surface 6), optiland's default
                compensator optimiser (method='generic': scipy.optimize.minimize,
                L-BFGS-B as bounds are passed, tol=1e-5) on the same operands.

Each sampler is a DistributionSampler with its own seed (SEED*1000 + its number).
Measured: process CPU and wall seconds of MonteCarlo.run(), per trial (the time
between successive Tolerancing.reset() calls, which MonteCarlo.run makes at the
start of each trial), operand calls, and percentiles 50/90/98 of every operand,
of the merit (sum of squares) and of the compensator.
Options: --trials N (100), --seed S (37), --index, --json PATH, --verbose.
"""

import argparse
import json
import math
import sys
import time

import numpy as np

sys.dont_write_bytecode = True   # no __pycache__ inside the repository

import cooke_common as cc
from optiland.materials.base import BaseMaterial
from optiland.optimization.operand.operand import operand_registry
from optiland.tolerancing import Tolerancing
from optiland.tolerancing.monte_carlo import MonteCarlo
from optiland.tolerancing.perturbation import DistributionSampler

RADIUS_REL = 1e-3
THICKNESS_MM = 0.02
DECENTER_MM = 0.01
TILT_DEG = 0.01
INDEX_DN = 5e-4
PERCENTILES = (50, 90, 98)


class OffsetGlass(BaseMaterial):
    """A catalog glass with a constant index offset dn at every wavelength."""

    def __init__(self, glass):
        super().__init__()
        self.glass = glass
        self.dn = 0.0

    def set_offset(self, dn):
        self.dn = float(dn)
        self._n_cache.clear()      # BaseMaterial caches n by wavelength only

    def _calculate_n(self, wavelength, **kwargs):
        return self.glass.n(wavelength, **kwargs) + self.dn

    def _calculate_k(self, wavelength, **kwargs):
        return self.glass.k(wavelength, **kwargs)

    def to_dict(self):
        return {"type": "OffsetGlass", "glass": self.glass.to_dict(), "dn": self.dn}


class IndexOffsetPerturbation:
    """Duck-typed optiland Perturbation (apply/reset/value/variable) for dn."""

    def __init__(self, optic, surface_number, sampler):
        glass = optic.surfaces[surface_number].material_post
        self.material = OffsetGlass(glass)
        optic.updater.set_material(self.material, surface_number)
        self.sampler = sampler
        self.value = 0.0
        self.variable = f"Index offset, Surface {surface_number}"

    def apply(self):
        self.value = float(self.sampler.sample())
        self.material.set_offset(self.value)

    def reset(self):
        self.material.set_offset(0.0)
        self.value = 0.0


def quiet_compensator(tol):
    """CompensatorOptimizer.run() exactly, but with disp=False: optiland's default
    disp=True makes scipy's Fortran L-BFGS-B print a report on every trial."""
    comp = tol.compensator

    def run():
        return comp.get_optimizer()(comp).optimize(tol=comp.tol, disp=False)
    comp.run = run


def uniform(centre, half_width, seed):
    return DistributionSampler("uniform", seed=seed, low=centre - half_width,
                               high=centre + half_width)


def build(lens, seed, with_index):
    tol = Tolerancing(lens)
    seeds = iter(range(seed * 1000, seed * 1000 + 1000))
    for k in range(1, 7):
        radius = float(lens.surfaces.radii[k])
        tol.add_perturbation("radius", uniform(radius, abs(radius) * RADIUS_REL,
                                               next(seeds)), surface_number=k)
    for k in range(1, 6):
        t = float(lens.surfaces[k].thickness)
        tol.add_perturbation("thickness", uniform(t, THICKNESS_MM, next(seeds)),
                             surface_number=k)
    for k in range(1, 7):
        for axis in ("x", "y"):
            tol.add_perturbation("decenter", uniform(0.0, DECENTER_MM, next(seeds)),
                                 surface_number=k, axis=axis)
    for k in range(1, 7):
        for axis in ("x", "y"):
            tol.add_perturbation("tilt", uniform(0.0, math.radians(TILT_DEG),
                                                 next(seeds)),
                                 surface_number=k, axis=axis)
    if with_index:
        for k in (1, 3, 5):
            tol.perturbations.append(IndexOffsetPerturbation(
                lens, k, uniform(0.0, INDEX_DN, next(seeds))))

    for field in cc.FIELDS_DEG:
        tol.add_operand("rms_spot_size", target=0.0, weight=1.0, input_data={
            "optic": lens, "surface_number": -1, "Hx": 0.0,
            "Hy": cc.field_hy(field), "num_rays": cc.NUM_RINGS,
            "wavelength": "all", "distribution": cc.DISTRIBUTION})
    tol.add_operand("f2", target=cc.EFL_TARGET, weight=1.0,
                    input_data={"optic": lens})
    tol.add_compensator("thickness", surface_number=6)
    return tol


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--trials", type=int, default=100)
    parser.add_argument("--seed", type=int, default=37)
    parser.add_argument("--index", action="store_true",
                        help="add the +-5e-4 index offsets (see the docstring)")
    parser.add_argument("--json", help="write all results to this file")
    parser.add_argument("--verbose", action="store_true",
                        help="let the compensator's L-BFGS-B print")
    args = parser.parse_args()

    lens = cc.nominal_lens()
    efl_plain = cc.efl(lens)
    tol = build(lens, args.seed, args.index)
    if not args.verbose:
        quiet_compensator(tol)
    # The OffsetGlass wrapper at dn = 0 must reproduce the catalog glass exactly.
    assert cc.efl(lens) == efl_plain, (cc.efl(lens), efl_plain)

    names = ["RMS 0 deg", "RMS 14 deg", "RMS 20 deg", "EFL"]
    nominal = tol.evaluate()
    tol.apply_compensators()
    nominal_comp = tol.evaluate()
    nominal_bf = float(lens.surfaces[6].thickness)
    tol.reset()

    # Per-trial CPU: MonteCarlo.run() calls tolerancing.reset() first in each trial.
    stamps = []
    original_reset = tol.reset

    def stamped_reset():
        stamps.append((time.process_time(), time.perf_counter()))
        original_reset()
    tol.reset = stamped_reset

    calls = {"rms_spot_size": 0, "f2": 0}
    for name in calls:
        func = operand_registry.get(name)

        def counted(*a, _f=func, _n=name, **kw):
            calls[_n] += 1
            return _f(*a, **kw)
        operand_registry.register(name, counted, overwrite=True)

    mc = MonteCarlo(tol)
    load_start = cc.load_average()
    cpu0, wall0 = time.process_time(), time.perf_counter()
    mc.run(num_iterations=args.trials)
    cpu, wall = time.process_time() - cpu0, time.perf_counter() - wall0
    stamps.append((cpu0 + cpu, wall0 + wall))
    load_end = cc.load_average()
    tol.reset = original_reset
    tol.reset()

    df = mc.get_results()
    op_cols = list(mc.operand_names)     # MonteCarlo's column names, in order
    values = df[op_cols].to_numpy(dtype=float)
    targets = np.array([0.0, 0.0, 0.0, cc.EFL_TARGET])
    merit = np.sum((values - targets) ** 2, axis=1)
    comp_col = [c for c in df.columns if c.startswith("C0")][0]
    comp = df[comp_col].to_numpy(dtype=float)

    trial_cpu = np.diff([s[0] for s in stamps])
    trial_wall = np.diff([s[1] for s in stamps])

    def pct(x):
        return {f"p{p}": float(np.percentile(x, p)) for p in PERCENTILES} | {
            "mean": float(np.mean(x)), "min": float(np.min(x)),
            "max": float(np.max(x))}

    out = {
        "optiland_commit": cc.optiland_commit(),
        "python": sys.version.split()[0],
        "trials": args.trials, "seed": args.seed, "index_offsets": args.index,
        "tolerances": {"radius_rel": RADIUS_REL, "thickness_mm": THICKNESS_MM,
                       "decenter_mm": DECENTER_MM, "tilt_deg": TILT_DEG,
                       "index_dn": INDEX_DN if args.index else None,
                       "distribution": "uniform +-tol"},
        "num_perturbations": len(tol.perturbations),
        "sampling": {"distribution": cc.DISTRIBUTION, "num_rings": cc.NUM_RINGS},
        "load_start": load_start, "load_end": load_end,
        "cpu_s": cpu, "wall_s": wall,
        "cpu_per_trial_s": pct(trial_cpu), "wall_per_trial_s": pct(trial_wall),
        "operand_calls": calls,
        "nominal": dict(zip(names, map(float, nominal))),
        "nominal_merit": float(np.sum((np.array(nominal) - targets) ** 2)),
        "nominal_compensated": dict(zip(names, map(float, nominal_comp))),
        "nominal_compensated_back_focus": nominal_bf,
        "percentiles": {n: pct(values[:, i]) for i, n in enumerate(names)},
        "merit_percentiles": pct(merit),
        "back_focus_percentiles": pct(comp),
        "operand_columns": op_cols,
    }

    print(f"optiland commit {out['optiland_commit']}; {args.trials} trials, seed "
          f"{args.seed}, {len(tol.perturbations)} perturbations"
          f"{' (with index offsets)' if args.index else ''}")
    print(f"load start {load_start} / end {load_end}")
    print(f"nominal: {out['nominal']} merit {out['nominal_merit']:.9g}")
    print(f"nominal, focus compensated: {out['nominal_compensated']} "
          f"back focus {nominal_bf:.6f}")
    print(f"CPU {cpu:.2f} s, wall {wall:.2f} s; per trial CPU {out['cpu_per_trial_s']}")
    print(f"operand calls: {calls}")
    for n in names:
        p = out["percentiles"][n]
        print(f"  {n:<11} p50 {p['p50']:.7g}  p90 {p['p90']:.7g}  p98 {p['p98']:.7g}")
    p = out["merit_percentiles"]
    print(f"  {'merit':<11} p50 {p['p50']:.7g}  p90 {p['p90']:.7g}  p98 {p['p98']:.7g}")
    p = out["back_focus_percentiles"]
    print(f"  {'back focus':<11} p50 {p['p50']:.7g}  p90 {p['p90']:.7g}  p98 {p['p98']:.7g}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
