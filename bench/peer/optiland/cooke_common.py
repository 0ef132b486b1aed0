"""Shared pieces of the optiland peer runs for lenslab issue 37.

The lens, the merit function and the small measuring helpers used by both
cooke_optimise.py and cooke_tolerance.py. optiland itself comes from
PYTHONPATH (an exported snapshot outside this repository, see setup.sh).
"""

import os

# One BLAS/OpenMP thread: this machine is shared (2 cores, another build runs)
# and process_time() then measures one core's work. Must precede numpy.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
             "NUMBA_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import subprocess  # noqa: E402

import numpy as np  # noqa: E402

import optiland  # noqa: E402
from optiland import optimization  # noqa: E402
from optiland.optimization.operand.ray import RayOperand  # noqa: E402
from optiland.samples.objectives import CookeTriplet  # noqa: E402

# Merit sampling. optiland's rms_spot_size operand has no default ray count
# (num_rays is a required argument); its default distribution is 'hexapolar',
# where num_rays is the number of rings: 1 + 3*n*(n+1) pupil points, rings at
# r = k/n (k = 1..n) with 6k equally spaced points from theta = 0, plus the
# centre. n = 5 (91 rays per wavelength) is what optiland's own Cooke-triplet
# tutorials use (Tutorial_5c, 8a, 8b).
NUM_RINGS = 5
DISTRIBUTION = "hexapolar"

FIELDS_DEG = (0.0, 14.0, 20.0)
MAX_FIELD_DEG = 20.0
WAVELENGTHS_UM = (0.48, 0.55, 0.65)
EFL_TARGET = 50.0

# Curvature factors of the issue-37 start point: +5%, -5%, alternately.
CURVATURE_FACTORS = (1.05, 0.95, 1.05, 0.95, 1.05, 0.95)


def optiland_commit():
    """Commit of the optiland snapshot, if its bare git dir is known."""
    git_dir = os.environ.get(
        "OPTILAND_GIT_DIR", "/work/.mirror/optiland+optiland/repo")
    try:
        return subprocess.run(
            ["git", "--git-dir", git_dir, "log", "-1", "--format=%H %ci"],
            capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def load_average():
    with open("/proc/loadavg") as f:
        return f.read().strip()


def nominal_lens():
    """optiland's CookeTriplet sample, unchanged."""
    lens = CookeTriplet()
    lens.update_paraxial()
    return lens


def perturb_curvatures(lens):
    """Issue-37 start point: curvature c of surface k times CURVATURE_FACTORS[k-1]."""
    for k, factor in enumerate(CURVATURE_FACTORS, start=1):
        radius = float(lens.surfaces.radii[k])
        lens.updater.set_radius(radius / factor, k)   # 1/(c*f) = R/f
    lens.update_paraxial()
    return lens


def radii(lens):
    return [float(lens.surfaces.radii[k]) for k in range(1, 7)]


def field_hy(field_deg):
    """optiland's normalised field coordinate for an angle field."""
    return field_deg / MAX_FIELD_DEG


def add_merit(problem, lens):
    """Issue-37 merit: 3 polychromatic RMS spots (target 0, weight 1) + EFL 50."""
    for field in FIELDS_DEG:
        problem.add_operand(
            operand_type="rms_spot_size", target=0.0, weight=1.0,
            input_data={"optic": lens, "surface_number": -1, "Hx": 0.0,
                        "Hy": field_hy(field), "num_rays": NUM_RINGS,
                        "wavelength": "all", "distribution": DISTRIBUTION})
    problem.add_operand(operand_type="f2", target=EFL_TARGET, weight=1.0,
                        input_data={"optic": lens})
    return problem


def make_problem(lens, with_variables=True):
    problem = optimization.OptimizationProblem()
    add_merit(problem, lens)
    if with_variables:
        for k in range(1, 7):
            problem.add_variable(lens, "radius", surface_number=k)
    return problem


def merit(problem):
    """optiland's merit: sum over operands of weight * (value - target)^2."""
    return float(problem.sum_squared())


def rms_spot(lens, field_deg, wavelength, num_rings=NUM_RINGS,
             distribution=DISTRIBUTION):
    """optiland's rms_spot_size operand value (mm) on the image surface.

    wavelength='all': every wavelength's rays pooled with equal weight, radius
    measured from the PRIMARY wavelength's centroid (optiland's definition).
    A single wavelength: radius about that wavelength's own centroid.
    """
    return float(RayOperand.rms_spot_size(
        lens, -1, 0.0, field_hy(field_deg), num_rings, wavelength, distribution))


def rms_spot_poly_centroid(lens, field_deg, num_rings=NUM_RINGS,
                           distribution=DISTRIBUTION):
    """Variant for cross-checks: pooled rays about the POOLED centroid (mm)."""
    xs, ys = [], []
    for wave in WAVELENGTHS_UM:
        lens.trace(0.0, field_hy(field_deg), wave, num_rings, distribution)
        xs.append(np.asarray(lens.surfaces.x[-1, :]).ravel())
        ys.append(np.asarray(lens.surfaces.y[-1, :]).ravel())
    x, y = np.concatenate(xs), np.concatenate(ys)
    return float(np.sqrt(np.mean((x - x.mean()) ** 2 + (y - y.mean()) ** 2)))


def efl(lens):
    return float(lens.paraxial.f2())


def first_order(lens):
    """EFL, BFL and image distances at the primary wavelength (mm)."""
    t_last = float(lens.surfaces[-2].thickness)         # surface 6 -> image
    f2_from_image = float(lens.paraxial.F2())            # F2 relative to image
    ya, ua = lens.paraxial.marginal_ray()
    marginal_focus_from_image = float(-ya[-1, 0] / ua[-1, 0])
    return {
        "EFL": efl(lens),
        "BFL (surface 6 vertex -> paraxial focal point F')": t_last + f2_from_image,
        "image distance (surface 6 thickness, as given)": t_last,
        "paraxial image (marginal ray crossing) from surface 6": (
            t_last + marginal_focus_from_image),
        "paraxial focus - image plane": f2_from_image,
    }


def optiland_version():
    return getattr(optiland, "__version__", "?")
