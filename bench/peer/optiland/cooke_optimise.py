#!/usr/bin/python3
"""optiland as a peer for lenslab issue 37: the Cooke triplet optimisation.

    PYTHONPATH=/work/peers/optiland /usr/bin/python3 bench/peer/optiland/cooke_optimise.py

What it does (all in optiland, numpy backend, float64):
  1. Prints the CookeTriplet sample's prescription, the catalog entries optiland
     resolved "SK16" and ("F2", "schott") to, and its refractive indices at
     0.48, 0.55, 0.65 and 0.5875618 um.
  2. Nominal design: first order (EFL, BFL, image distance), RMS spot radius per
     field per wavelength and polychromatic, and the issue-37 merit.
  3. Start point: each curvature 5% off (c*1.05, c*0.95, ... on surfaces 1-6).
  4. optiland's LeastSquares optimiser with its defaults (optimize(): tol=1e-3,
     method_choice='lm'; with 4 residuals < 6 variables optiland itself switches
     to scipy 'trf'), variables the six radii (optiland 'radius' variables, their
     default scaler), run until it stops, 3 times from a freshly built start
     point. Measured per repeat: process CPU and wall seconds of optimize(),
     merit evaluations (calls of the residual vector, each computing all four
     operands; finite-difference Jacobian columns included) and operand calls.

Merit: sum_i w_i (value_i - target_i)^2 = RMS(0)^2 + RMS(14)^2 + RMS(20)^2
+ (EFL - 50)^2 with RMS in mm (optiland's problem.sum_squared()).
Options: --repeats N (default 3), --json PATH (write every number).
"""

import argparse
import json
import sys
import time

sys.dont_write_bytecode = True   # no __pycache__ inside the repository

import cooke_common as cc
from optiland import optimization
from optiland.optimization.operand.operand import operand_registry

INDEX_WAVELENGTHS = (0.48, 0.55, 0.65, 0.5875618)


class CountingLeastSquares(optimization.LeastSquares):
    """optiland's LeastSquares, counting residual-vector (merit) evaluations."""

    def __init__(self, problem):
        super().__init__(problem)
        self.n_merit_evals = 0

    def _compute_residuals_vector(self, x):
        self.n_merit_evals += 1
        return super()._compute_residuals_vector(x)


class OperandCounter:
    """Counts calls of the operand functions by wrapping optiland's registry."""

    def __init__(self, names=("rms_spot_size", "f2")):
        self.calls = {}
        for name in names:
            func = operand_registry.get(name)
            self.calls[name] = 0
            operand_registry.register(name, self._wrap(name, func),
                                      overwrite=True)

    def _wrap(self, name, func):
        def counted(*args, **kwargs):
            self.calls[name] += 1
            return func(*args, **kwargs)
        return counted

    def reset(self):
        for name in self.calls:
            self.calls[name] = 0


def prescription(lens):
    rows = []
    for k, surface in enumerate(lens.surfaces):
        mat = surface.material_post
        if type(mat).__name__ == "IdealMaterial":
            name = f"ideal n={float(mat.index.ravel()[0]) if hasattr(mat.index, 'ravel') else float(mat.index)}"
            entry = ""
        else:
            name = mat.name + (f" ({mat.reference})" if mat.reference else "")
            data = mat.material_data
            entry = f"{data['filename']} [{data['category_name_full']}]"
        rows.append({
            "surface": k,
            "radius": float(lens.surfaces.radii[k]),
            "thickness": float(surface.thickness),
            "material_after": name,
            "catalog_entry": entry,
            "is_stop": bool(surface.is_stop),
        })
    return rows


def glass_indices(lens):
    out = {}
    for k in (1, 3):
        mat = lens.surfaces[k].material_post
        data = mat.material_data
        out[f"{mat.name} ({data['filename']})"] = {
            f"{w:g}": float(mat.n(w)) for w in INDEX_WAVELENGTHS}
    return out


def spot_table(lens):
    table = {}
    for field in cc.FIELDS_DEG:
        row = {f"{w:g}": cc.rms_spot(lens, field, w) for w in cc.WAVELENGTHS_UM}
        row["poly (optiland: primary centroid)"] = cc.rms_spot(lens, field, "all")
        row["poly (pooled centroid)"] = cc.rms_spot_poly_centroid(lens, field)
        table[f"{field:g} deg"] = row
    return table


def poly_spots(lens):
    return {f"{f:g} deg": cc.rms_spot(lens, f, "all") for f in cc.FIELDS_DEG}


def one_run(counter):
    """Build the start point, optimise it, return the measurements."""
    lens = cc.perturb_curvatures(cc.nominal_lens())
    problem = cc.make_problem(lens)
    start_radii = cc.radii(lens)
    merit_before = cc.merit(problem)
    efl_before = cc.efl(lens)
    spots_before = poly_spots(lens)

    optimizer = CountingLeastSquares(problem)
    counter.reset()
    cpu0, wall0 = time.process_time(), time.perf_counter()
    result = optimizer.optimize()          # optiland defaults, until it stops
    cpu, wall = time.process_time() - cpu0, time.perf_counter() - wall0
    operand_calls = dict(counter.calls)

    return {
        "cpu_s": cpu,
        "wall_s": wall,
        "merit_evaluations": optimizer.n_merit_evals,
        "operand_calls": operand_calls,
        "scipy_nfev": int(result.nfev),
        "scipy_njev": int(result.njev) if result.njev is not None else None,
        "scipy_status": int(result.status),
        "scipy_message": str(result.message),
        "start_radii": start_radii,
        "merit_before": merit_before,
        "efl_before": efl_before,
        "spots_before_mm": spots_before,
        "radii_after": cc.radii(lens),
        "merit_after": cc.merit(problem),
        "efl_after": cc.efl(lens),
        "spots_after_mm": poly_spots(lens),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--json", help="write all results to this file")
    args = parser.parse_args()

    out = {"optiland_commit": cc.optiland_commit(),
           "optiland_version": cc.optiland_version(),
           "python": sys.version.split()[0],
           "load_start": cc.load_average(),
           "sampling": {"operand": "rms_spot_size", "distribution": cc.DISTRIBUTION,
                        "num_rings": cc.NUM_RINGS,
                        "rays_per_wavelength": 1 + 3 * cc.NUM_RINGS * (cc.NUM_RINGS + 1)}}

    lens = cc.nominal_lens()
    out["prescription"] = prescription(lens)
    out["indices"] = glass_indices(lens)
    out["nominal_first_order"] = cc.first_order(lens)
    out["nominal_spots_mm"] = spot_table(lens)
    out["nominal_merit"] = cc.merit(cc.make_problem(lens, with_variables=False))

    print(f"optiland {out['optiland_version']} commit {out['optiland_commit']}")
    print(f"load: {out['load_start']}")
    print("\nPrescription (radius, thickness, material after the surface):")
    for r in out["prescription"]:
        stop = "  STOP" if r["is_stop"] else ""
        print(f"  {r['surface']}: R={r['radius']!r:>22} t={r['thickness']!r:>10} "
              f"{r['material_after']:<16} {r['catalog_entry']}{stop}")
    print("\nRefractive indices (relative to air, as optiland uses them):")
    for name, values in out["indices"].items():
        print(f"  {name}: " + "  ".join(f"n({w})={v:.7f}" for w, v in values.items()))
    print("\nNominal first order (primary 0.55 um):")
    for k, v in out["nominal_first_order"].items():
        print(f"  {k}: {v:.9f}")
    print(f"\nNominal RMS spot radius, mm ({cc.DISTRIBUTION}, {cc.NUM_RINGS} rings):")
    for field, row in out["nominal_spots_mm"].items():
        print(f"  {field}: " + "  ".join(f"{k}={v:.9f}" for k, v in row.items()))
    print(f"Nominal merit: {out['nominal_merit']:.12g}")

    counter = OperandCounter()
    runs = []
    for i in range(args.repeats):
        run = one_run(counter)
        runs.append(run)
        print(f"\nrepeat {i + 1}: CPU {run['cpu_s']:.3f} s, wall {run['wall_s']:.3f} s, "
              f"merit evaluations {run['merit_evaluations']} (scipy nfev "
              f"{run['scipy_nfev']}, njev {run['scipy_njev']}), operand calls "
              f"{run['operand_calls']}; {run['scipy_message']}")
    out["runs"] = runs
    out["load_end"] = cc.load_average()

    r = runs[0]
    print(f"\nstart radii: {r['start_radii']}")
    print(f"merit before {r['merit_before']:.12g} (EFL {r['efl_before']:.9f}), "
          f"after {r['merit_after']:.12g} (EFL {r['efl_after']:.9f})")
    print(f"radii after: {r['radii_after']}")
    print(f"spots before (mm): {r['spots_before_mm']}")
    print(f"spots after  (mm): {r['spots_after_mm']}")
    print(f"load: {out['load_end']}")

    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
