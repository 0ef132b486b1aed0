#!/usr/bin/python3
"""lenslab against ray-optics, an independent lens design program (issues 28 and 29).

For every prescription lenslab reads among the public ones (../shared/realworld/prescriptions:
*.zmx, *.seq, *.dat) and the bundled lenses (lenses/*.dat, *.zmx), at the F, d and C lines:
EFL, BFL, entrance and exit pupil positions and diameters and the f-number; and at the d line
the RMS spot radius on axis and at lenslab's largest field. Prints a Markdown table and, below
it, the notes the table refers to. A file lenslab refuses is listed with lenslab's message.

    PYTHONPATH=RAYOPTICS/src:OPTICALGLASS/src:ANYTREE/src:XLRD \\
        /usr/bin/python3 bench/peer/compare_rayoptics.py [--lenslab build/cli/lenslab] [--jobs N]
        [--no-spots] [--json RUN.json] [FILE...]
    /usr/bin/python3 bench/peer/compare_rayoptics.py --from-json RUN.json   (the tables again)

Requirements (Debian 12): python3-numpy, -scipy, -pandas, -matplotlib, -openpyxl, -parsimonious,
-transforms3d, -json-tricks, -deprecation, -requests, -packaging; ray-optics and opticalglass
(github mjhoptics/ray-optics, mjhoptics/opticalglass), anytree and xlrd (plain Python) from their
own source trees on PYTHONPATH, built outside this repository (bench/peer/rayoptics.md names the
commits). ray-optics' Qt GUI module is replaced by an empty one, and every network connection is
refused (ray-optics fetches some glasses, e.g. fused silica, from refractiveindex.info: such a
lens is reported as ray-optics' refusal).

How each number is obtained, on each side:
- lenslab: `lenslab lens FILE --json --wavelength NM` at each line (its widest aperture, focus at
  infinity), and `lenslab analyze FILE --json` (spots of the d line at fields 0 and 1, i.e. on axis
  and at its largest field; with `--image-plane paraxial` once the binary offers it).
- ray-optics: its own reader for .zmx and .seq; a .dat table (which it cannot read) is built here
  into ray-optics' sequential model from the table's radii, gaps, indices (or nd/Vd model glass,
  or catalog glass) and diameters. The wavelength list is set to F, d, C and the reference
  wavelength to the line compared. Its aperture is set from lenslab's stop opening at that line
  (lenslab's `stop.diameter`): the entrance pupil diameter that fills the stop paraxially, from
  ray-optics' own paraxial marginal ray. So EPD, XPD and f-number are ray-optics' results for the
  same physical stop opening. Positions: entrance pupil from the front vertex, exit pupil from the
  rear vertex, BFL from the rear vertex to F', all positive in the direction light travels there.
- f-number: lenslab's is 1 / (2 sin theta') of the real marginal ray at F' (README, Conventions);
  the script finds the same ray with ray-optics' trace (the meridional ray through the stop's rim
  and ray-optics' paraxial F') and compares. ray-optics' own f-number is paraxial, EFL/EPD =
  1/(2 n' u'), and is compared with EFL/EPD from lenslab's numbers.
- A first-order difference over the tolerance is looked into by the script: ray-optics is run again
  with lenslab's index of every medium at that line (a difference that vanishes then lies in the
  glass data), and every medium whose indices differ by over 1e-5 is listed with both programs'
  nF, nd, nC and the Abbe number they imply, Vd = (nd - 1) / (nF - nC), against the file's Vd.
- Spots (d line): rays are aimed with ray-optics' real trace by this script at points of the stop
  (Newton on the ray's start, apertures ignored while aiming, then traced with ray-optics' aperture
  checks), and cut with the image plane; the RMS radius is about the centroid. Two samplings:
  "hex10": lenslab's own analysis pattern (the centre and 10 hexapolar rings, 6k points on ring k,
  equal weights, uniform over the stop): the same rays lenslab traces, on lenslab's image plane;
  area-uniform: Gauss-Legendre in r^2 x equally spaced azimuths over the stop, or equal-area
  annuli x azimuths where the field is vignetted (Gaussian quadrature does not converge across
  the cut), the sampling doubled until the RMS moves by < 0.5% (up to 32 x 64), on lenslab's plane
  and on the paraxial image plane of the d line (the issue's definition). Off axis, ray-optics'
  own chief-ray aiming is checked: the table lists how far its chief ray crosses the stop from
  the centre.
"""
import argparse
import datetime
import glob
import json
import logging
import math
import os
import socket
import subprocess
import sys
import types

import numpy as np

LINES = (('F', 486.1327), ('d', 587.5618), ('C', 656.2725))
FIRST_ORDER_TOLERANCE = 2e-4   # relative (issues 28, 29)
SPOT_TOLERANCE = 0.02          # relative
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))


def refuse_network():
    def refuse(*args, **kwargs):
        raise OSError('compare_rayoptics: network access is refused')
    socket.socket.connect = refuse
    socket.create_connection = refuse
    socket.getaddrinfo = refuse


def import_rayoptics():
    """ray-optics without its Qt GUI: the one module that imports PySide6 is replaced by an empty one."""
    sys.modules['rayoptics.qtgui.guiappcmds'] = types.ModuleType('rayoptics.qtgui.guiappcmds')
    os.environ.setdefault('MPLBACKEND', 'Agg')
    logging.disable(logging.WARNING)
    global ro
    ro = types.SimpleNamespace()
    import rayoptics
    from rayoptics.gui.appcmds import open_model
    from rayoptics.optical.opticalmodel import OpticalModel
    from rayoptics.raytr.opticalspec import PupilSpec, FieldSpec, WvlSpec
    from rayoptics.raytr import trace as rtrace
    import rayoptics.raytr.raytrace as rt
    from rayoptics.raytr.traceerror import TraceError
    from opticalglass.opticalmedium import ConstantIndex
    from rayoptics.elem.surface import Circular
    ro.__dict__.update(locals())


def source_commit(module):
    """The git commit of the source tree a module was imported from, and its date."""
    import importlib
    where = os.path.dirname(importlib.import_module(module).__file__)
    p = subprocess.run(['git', '-C', where, 'log', '-1', '--format=%H %cs'], capture_output=True, text=True)
    return p.stdout.strip() or 'unknown (not a git checkout)'


def compare_in_worker(job):
    refuse_network()
    import_rayoptics()
    print(f'{os.path.basename(job[0])} ...', file=sys.stderr, flush=True)
    return compare(*job)


# ---------------------------------------------------------------------------------------------
# lenslab


def run_lenslab(binary, args):
    p = subprocess.run([binary, *args], capture_output=True, text=True)
    if p.returncode != 0:
        text = (p.stderr.strip() or p.stdout.strip() or f'exit {p.returncode}').splitlines()
        return None, text[0] if text else ''
    return p.stdout, None


def lenslab_json(binary, args):
    out, err = run_lenslab(binary, [*args, '--json'])
    return (json.loads(out), None) if out is not None else (None, err)


def analyze_has_image_plane(binary):
    out, _ = run_lenslab(binary, ['analyze', '--help'])
    return out is not None and '--image-plane' in out


# ---------------------------------------------------------------------------------------------
# lens tables (.dat): read here, built into ray-optics' model


def read_table(path):
    """Rows (radius, gap, N, diameter, fifth column or None) and the layout, detected as lenslab
    does: gap-before when the first row's gap is 0, gap-after when the last row's is."""
    rows = []
    with open(path, encoding='utf-8') as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            if not line:
                continue
            r, g, n, d = (float(v) for v in line[:4])
            rows.append((r, g, n, d, line[4] if len(line) > 4 else None))
    first, last = rows[0][1] == 0, rows[-1][1] == 0
    if first == last:
        raise ValueError('layout not detectable (first and last gap both zero or both not)')
    return rows, 'gap-before' if first else 'gap-after'


def build_table_model(path):
    rows, layout = read_table(path)
    gaps_after = ([row[1] for row in rows[1:]] + [0.0]) if layout == 'gap-before' else [row[1] for row in rows]
    opm = ro.OpticalModel(radius_mode=True)
    sm, osp = opm['seq_model'], opm['optical_spec']
    sm.do_apertures = False   # keep the table's diameters as the clear apertures
    sm.gaps[0].thi = 1e10
    osp['wvls'] = ro.WvlSpec([(nm, 1.0) for _, nm in LINES], ref_wl=1)
    osp['pupil'] = ro.PupilSpec(osp, key=['object', 'epd'], value=1.0)
    osp['fov'] = ro.FieldSpec(osp, key=['object', 'angle'], value=1.0, flds=[0., 1.], is_relative=True)
    for (r, _, n, d, fifth), thi in zip(rows, gaps_after):
        is_stop = r == 0 and n == 0
        if n in (0, 1):
            medium = ['air']
        elif fifth is None:
            medium = [n]
        else:
            try:
                medium = [n, float(fifth)]       # nd, Vd: ray-optics' model glass
            except ValueError:
                medium = [fifth]                 # a catalog glass, by name
        sm.add_surface([r, thi, *medium], sd=d / 2)
        if is_stop:
            sm.set_stop()
    opm.update_model()
    # The table gives no image distance: put the image surface at the paraxial focus.
    sm.gaps[-1].thi = opm['analysis_results']['parax_data'].fod.bfl
    opm.update_model()
    return opm


# ---------------------------------------------------------------------------------------------
# ray-optics: first order


def zemax_surface_lines(path):
    """{surface number: [its lines]} of a .zmx file (UTF-16 with a byte order mark, or UTF-8)."""
    with open(path, 'rb') as f:
        raw = f.read()
    text = raw.decode('utf-16') if raw[:2] in (b'\xff\xfe', b'\xfe\xff') else raw.decode('utf-8', 'replace')
    blocks, current = {}, None
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ['SURF']:
            current = int(words[1])
            blocks[current] = []
        elif current is not None and words:
            blocks[current].append(words)
    return blocks


def fix_zemax_apertures(opm, path):
    """Two apertures ray-optics' .zmx reader gets wrong at this commit, set as the file says:
    `DIAM r 2 s ...` is a semi-diameter picked up from surface s (the second field is the
    semi-diameter's solve type), which ray-optics takes for aperture type 2, an obscuration; and
    `OBSC rmin rmax` (a central obscuration) is not read at all. Returns what was changed."""
    changed = []
    sm = opm['seq_model']
    for n, lines in zemax_surface_lines(path).items():
        if not 0 < n < len(sm.ifcs) - 1:
            continue
        ifc = sm.ifcs[n]
        for words in lines:
            if words[0] == 'DIAM' and len(words) > 2 and words[2] == '2':
                for ca in ifc.clear_apertures:
                    if ca.is_obscuration:
                        ca.is_obscuration = False
                        changed.append(f'surface {n}: DIAM pickup read as an obscuration, made the clear aperture')
            if words[0] == 'OBSC' and len(words) > 2 and float(words[2]) > 0:
                ifc.clear_apertures.append(ro.Circular(radius=float(words[2]), is_obscuration=True))
                changed.append(f'surface {n}: OBSC {words[2]} added (ray-optics ignores OBSC)')
    return changed


def load_rayoptics(path, notes=None):
    if path.endswith('.dat'):
        return build_table_model(path)
    opm = ro.open_model(path)
    if path.endswith('.zmx'):
        changed = fix_zemax_apertures(opm, path)
        if notes is not None:
            notes.extend(changed)
    return opm


def set_line(opm, nm):
    osp = opm['optical_spec']
    osp['wvls'] = ro.WvlSpec([(w, 1.0) for _, w in LINES], ref_wl=[w for _, w in LINES].index(nm))
    opm.update_model()


def fill_stop(opm, stop_index, stop_radius):
    """Sets ray-optics' entrance pupil diameter so that its paraxial marginal ray fills the stop
    (surface stop_index of ray-optics' sequence) at stop_radius; twice, as the first pass may start
    from a pupil spec of another kind (f-number, NA)."""
    osp = opm['optical_spec']
    for _ in range(2):
        fod = opm['analysis_results']['parax_data'].fod
        ax = opm['analysis_results']['parax_data'].ax_ray
        epd = 2 * fod.enp_radius * stop_radius / abs(ax[stop_index][0])
        osp['pupil'] = ro.PupilSpec(osp, key=['object', 'epd'], value=epd)
        opm.update_model()


def rayoptics_first_order(opm):
    pd = opm['analysis_results']['parax_data']
    fod, pr = pd.fod, pd.pr_ray
    sm = opm['seq_model']
    last = len(sm.ifcs) - 2
    # Exit pupil: where the paraxial chief ray leaving the last surface crosses the axis, from
    # that surface, along the light (ray-optics' slopes are along its local z, which a mirror
    # turns: z_dir says which way the light runs).
    exp = -pr[last][0] / pr[last][1] * sm.z_dir[last]
    return {'efl': fod.efl, 'bfl': fod.bfl * sm.z_dir[last], 'enp_pos': fod.enp_dist, 'enp_d': 2 * fod.enp_radius,
            'exp_pos': exp, 'exp_d': 2 * fod.exp_radius, 'fno': fod.fno}


def lenslab_first_order(j):
    s = j['surfaces']
    front, rear = s[0]['z'], s[-1]['z']
    # lens z runs toward the scene; light leaves the last surface toward -z unless an odd
    # number of mirrors turned it.
    out_dir = -1 if sum(1 for x in s if x['mirror']) % 2 == 0 else 1
    return {'efl': j['efl'], 'bfl': j['back_focal_distance'], 'enp_pos': front - j['entrance_pupil']['z'],
            'enp_d': j['entrance_pupil']['diameter'], 'exp_pos': (j['exit_pupil']['z'] - rear) * out_dir,
            'exp_d': j['exit_pupil']['diameter'], 'fno': j['efl'] / j['entrance_pupil']['diameter'],
            'fstop': j['fstop']}


def real_fstop(opm, stop_index, stop_radius, nm):
    """lenslab's f-number (README: 1 / (2 sin theta'), theta' the angle at F' of the marginal ray
    that fills the stop) with ray-optics' real trace: the meridional ray that crosses the stop at
    its rim and passes through the paraxial focus F' (ray-optics' BFL), found by Newton on its
    height and slope in front of the lens."""
    sm = opm['seq_model']
    fod = opm['analysis_results']['parax_data'].fod
    z0 = fod.obj_dist - 1000.0 - 2 * abs(fod.enp_dist)
    f_prime = fod.bfl

    def miss(v):
        d = np.array([0.0, v[1], 1.0]) / math.hypot(1.0, v[1])
        ray, _, _ = ro.rt.trace(sm, np.array([0.0, v[0], z0]), d, nm, intersect_obj=False)
        p, out = np.array(ray[-2][0]), np.array(ray[-2][1])
        return np.array([ray[stop_index][0][1] - stop_radius, p[1] + (f_prime - p[2]) / out[2] * out[1]]), out

    v = np.array([fod.enp_radius * stop_radius / abs(opm['analysis_results']['parax_data'].ax_ray[stop_index][0]), 0.0])
    for _ in range(40):
        f, out = miss(v)
        if np.hypot(*f) < 1e-11 * stop_radius:
            return 1 / (2 * abs(out[1]))
        h = 1e-7 * max(stop_radius, 1.0)
        jac = np.column_stack([(miss(v + dv)[0] - f) / h for dv in (np.array([h, 0.0]), np.array([0.0, h * 1e-2]))])
        jac[:, 1] *= 1e2
        v = v - np.linalg.solve(jac, f)
    return float('nan')


# ---------------------------------------------------------------------------------------------
# ray-optics: real rays aimed at the stop


class Aimer:
    """Rays of one field (object at infinity, angle in degrees) aimed with ray-optics' trace at
    points of the stop: a ray is named by where it crosses the paraxial entrance pupil plane and is
    moved there by Newton steps until it crosses the stop at the target (the Jacobian is kept from
    ray to ray and taken anew when a step does not shrink the miss tenfold). Rays start a short way
    in front of the lens rather than at ray-optics' object plane 1e10 mm away, where a start point
    carries 1e-6 mm of rounding."""

    def __init__(self, opm, stop_index, field_deg, nm):
        self.sm, self.nm, self.stop = opm['seq_model'], nm, stop_index
        fod = opm['analysis_results']['parax_data'].fod
        t = math.radians(field_deg)
        self.dir = np.array([0.0, -math.sin(t), math.cos(t)])   # lenslab's sign: toward -y
        self.z_aim = fod.obj_dist + fod.enp_dist
        self.z_start = fod.obj_dist - 1000.0 - 2 * abs(fod.enp_dist)
        self.scale = fod.enp_radius
        self.jac = None
        try:
            self.chief = self.aim(np.zeros(2))
        except (RuntimeError, ro.TraceError, np.linalg.LinAlgError):
            self.chief = self.chief_by_continuation(t)

    def chief_by_continuation(self, t):
        """A wide field's chief ray, found by walking the field up from the axis in 16 steps, each
        aimed from the last one's solution (a fisheye's pupil moves far from the paraxial one)."""
        a = np.zeros(2)
        for k in range(1, 17):
            s = t * k / 16
            self.dir = np.array([0.0, -math.sin(s), math.cos(s)])
            self.jac = None
            a = self.aim(np.zeros(2), guess=a)
        return a

    def start(self, a):
        p = np.array([a[0], a[1], self.z_aim])
        return p - ((p[2] - self.z_start) / self.dir[2]) * self.dir

    def trace(self, a, **kwargs):
        ray, _, _ = ro.rt.trace(self.sm, self.start(a), self.dir, self.nm, intersect_obj=False, **kwargs)
        return ray

    def at_stop(self, a):
        return np.array(self.trace(a)[self.stop][0][:2])

    def jacobian(self, a, at_a):
        h = 1e-6 * self.scale
        return np.column_stack([(self.at_stop(a + dv) - at_a) / h for dv in (np.array([h, 0]), np.array([0, h]))])

    def aim(self, target, guess=None):
        a = np.array(target if guess is None else guess, dtype=float)
        f = self.at_stop(a) - target
        if self.jac is None:
            self.jac = self.jacobian(a, f + target)
        for _ in range(12):
            miss = np.hypot(*f)
            if miss < 1e-10 * self.scale:
                return a
            a = a - np.linalg.solve(self.jac, f)
            f = self.at_stop(a) - target
            if np.hypot(*f) > 0.1 * miss:
                self.jac = self.jacobian(a, f + target)
        raise RuntimeError('aiming did not converge')

    def image_point(self, a, image_s):
        """Where the ray from start a meets the plane image_s from the last surface (along its local
        z), or None when an aperture blocks it."""
        try:
            ray = self.trace(a, check_apertures=True)
        except ro.TraceError:
            return None
        p, d = np.array(ray[-2][0]), np.array(ray[-2][1])
        t = (image_s - p[2]) / d[2]
        return p[:2] + t * d[:2]


def hexapolar(rings=10):
    pts, w = [(0.0, 0.0)], [1.0]
    for k in range(1, rings + 1):
        for j in range(6 * k):
            a = 2 * math.pi * j / (6 * k)
            pts.append((k / rings * math.sin(a), k / rings * math.cos(a)))
            w.append(1.0)
    return np.array(pts), np.array(w)


def gauss_r2(n_r, n_az):
    u, wu = np.polynomial.legendre.leggauss(n_r)
    u, wu = (u + 1) / 2, wu / 2
    pts, w = [], []
    for uj, wj in zip(u, wu):
        for k in range(n_az):
            a = 2 * math.pi * (k + 0.5) / n_az
            pts.append((math.sqrt(uj) * math.sin(a), math.sqrt(uj) * math.cos(a)))
            w.append(wj)
    return np.array(pts), np.array(w)


def rms_spot(aimer, stop_radius, image_s, pattern):
    pts, w = pattern
    hits, ws, failed, aimed = [], [], 0, 0
    a = aimer.chief
    for (px, py), wi in zip(pts, w):
        target = np.array([px, py]) * stop_radius
        try:
            a = aimer.aim(target, guess=a)   # from the last ray aimed, a neighbour
        except (RuntimeError, ro.TraceError, np.linalg.LinAlgError):
            try:
                aimer.jac = None   # the kept Jacobian may belong to a far part of the pupil
                a = aimer.aim(target, guess=aimer.chief)
            except (RuntimeError, ro.TraceError, np.linalg.LinAlgError):
                failed += 1
                if failed > 64 and not aimed:   # no point of this stop is within the field's reach
                    return float('nan'), 0
                continue
        aimed += 1
        q = aimer.image_point(a, image_s)
        if q is not None:
            hits.append(q)
            ws.append(wi)
    if not hits:
        return float('nan'), 0
    hits, ws = np.array(hits), np.array(ws)
    c = (ws[:, None] * hits).sum(0) / ws.sum()
    return math.sqrt((ws * ((hits - c) ** 2).sum(1)).sum() / ws.sum()), len(hits)


def equal_area(n_r, n_az):
    """n_r annuli of equal area, each at its mid-area radius, times n_az azimuths, equal weights."""
    pts = [(math.sqrt((j + 0.5) / n_r) * math.sin(2 * math.pi * (k + 0.5) / n_az),
            math.sqrt((j + 0.5) / n_r) * math.cos(2 * math.pi * (k + 0.5) / n_az))
           for j in range(n_r) for k in range(n_az)]
    return np.array(pts), np.ones(len(pts))


def converged_rms(aimer, stop_radius, image_s):
    """(RMS, rays passed, sampling): Gauss-Legendre in r^2 while no ray is blocked; where the
    aperture is vignetted (a cut through the pupil, which Gaussian quadrature does not converge
    on) equal-area annuli. n_r doubles (azimuths 2 n_r) until the RMS moves by < 0.5%, up to 32."""
    rule, name, n = gauss_r2, 'gauss', 8
    prev, count = rms_spot(aimer, stop_radius, image_s, rule(n, 2 * n))
    if count < n * 2 * n:
        rule, name = equal_area, 'equal-area'
        prev, count = rms_spot(aimer, stop_radius, image_s, rule(n, 2 * n))
    while True:
        n *= 2
        cur, count = rms_spot(aimer, stop_radius, image_s, rule(n, 2 * n))
        change = abs(cur - prev) / cur
        if change <= 0.005:
            return cur, count, f'{name} {n}x{2 * n}'
        if n >= 32:
            return cur, count, f'{name} {n}x{2 * n}, not converged ({change:.1%} from {n // 2}x{n})'
        prev = cur


def rayoptics_chief_miss(opm, stop_index, field_deg, nm):
    """ray-optics' own chief ray (its aiming, pupil (0, 0)) for the field: its height at the stop."""
    osp = opm['optical_spec']
    osp['fov'] = ro.FieldSpec(osp, key=['object', 'angle'], value=field_deg, flds=[0., 1.], is_relative=True)
    opm.update_model()
    fld = osp['fov'].fields[1]
    rr = ro.rtrace.trace_ray(opm, np.array([0., 0.]), fld, nm, check_apertures=False)
    ray = rr.pkg.ray if hasattr(rr, 'pkg') else rr[0].ray
    return float(np.hypot(*ray[stop_index][0][:2]))


def paraxial_image_s(aimer, stop_radius):
    """The d line's paraxial focus, as distance from the last surface along its local z: where a
    ray through the stop at 1e-5 of its radius crosses the axis."""
    ray = aimer.trace(aimer.aim(np.array([0.0, 1e-5 * stop_radius]), guess=aimer.chief))
    p, d = np.array(ray[-2][0]), np.array(ray[-2][1])
    return p[2] - p[1] / d[1] * d[2]


# ---------------------------------------------------------------------------------------------
# one prescription


def relative(a, b, scale=None):
    return (a - b) / abs(scale if scale is not None else b)


def with_lenslab_indices(opm, surfaces):
    """ray-optics' model with every medium replaced by lenslab's index at the current line."""
    sm = opm['seq_model']
    for k, s in enumerate(surfaces):
        sm.gaps[k + 1].medium = ro.ConstantIndex(abs(s['n']), 'lenslab')
    opm.update_model()


def abbe(n):
    return (n[1] - 1) / (n[0] - n[2]) if n[0] != n[2] else float('inf')


def glass_notes(opm, lenslab):
    """The media whose indices differ by more than 1e-5 at a line: what each program takes, and
    the closed-form check Vd = (nd - 1) / (nF - nC) against the Vd the file states (ray-optics'
    reading of it, for a model glass)."""
    sm, notes = opm['seq_model'], []
    for k, s in enumerate(lenslab['d']['surfaces']):
        m = sm.gaps[k + 1].medium
        n_ll = [abs(lenslab[name]['surfaces'][k]['n']) for name, _ in LINES]
        n_ro = [m.rindex(nm) for _, nm in LINES]
        if max(abs(a - b) for a, b in zip(n_ll, n_ro)) <= 1e-5:
            continue
        stated = f', the file\'s Vd {m.v:.4g}' if hasattr(m, 'v') else ''
        note = (f'{s["glass"] or "model"}{" " + s["catalog"] if s["catalog"] else ""}: lenslab nF nd nC '
                f'{n_ll[0]:.6f} {n_ll[1]:.6f} {n_ll[2]:.6f} (Vd {abbe(n_ll):.4g}); ray-optics {type(m).__name__} '
                f'{m.name()}: {n_ro[0]:.6f} {n_ro[1]:.6f} {n_ro[2]:.6f} (Vd {abbe(n_ro):.4g}){stated}')
        if note not in notes:
            notes.append(note)
    return notes


def compare(path, binary, paraxial_flag, with_spots=True):
    """A dict: 'refused' (who and why), or 'lines' (first order per line) and 'spots'."""
    out = {'file': path, 'notes': []}
    lenslab = {}
    for name, nm in LINES:
        j, err = lenslab_json(binary, ['lens', path, '--wavelength', repr(nm)])
        if err is not None:
            out['refused'] = err.replace(os.path.dirname(path) + os.sep, '')
            return out
        lenslab[name] = j
    try:
        opm = load_rayoptics(path, out['notes'])
    except Exception as e:   # ray-optics' readers raise many kinds
        out['refused'] = f'ray-optics: {type(e).__name__}: {str(e).splitlines()[0][:160]}'
        return out
    sm = opm['seq_model']
    surfaces = lenslab['d']['surfaces']
    if len(sm.ifcs) - 2 != len(surfaces):
        out['refused'] = f'not compared: ray-optics has {len(sm.ifcs) - 2} surfaces, lenslab {len(surfaces)}'
        return out
    stop = lenslab['d']['stop']['surface'] + 1
    if sm.stop_surface != stop:
        out['notes'].append(f'ray-optics had the stop at {sm.stop_surface}; set to lenslab\'s, surface {stop}')
        sm.stop_surface = stop
    if not path.endswith('.dat'):   # a table states no field
        out['file_field'] = opm['optical_spec']['fov'].max_field()[0]
        out['file_field_key'] = ' '.join(opm['optical_spec']['fov'].key)
    out['lines'] = []
    for name, nm in LINES:
        j = lenslab[name]
        set_line(opm, nm)
        fill_stop(opm, stop, j['stop']['diameter'] / 2)
        dn = max(abs(abs(s['n']) - sm.gaps[k + 1].medium.rindex(nm)) for k, s in enumerate(j['surfaces']))
        first = rayoptics_first_order(opm)
        try:
            first['fstop'] = real_fstop(opm, stop, j['stop']['diameter'] / 2, nm)
        except (ro.TraceError, np.linalg.LinAlgError):
            first['fstop'] = float('nan')
        out['lines'].append({'line': name, 'nm': nm, 'll': lenslab_first_order(j), 'ro': first,
                             'dn': dn, 'stop_d': j['stop']['diameter']})
    # Differences over the tolerance: ray-optics again with lenslab's indices, which tells a
    # difference in glass data from one in the optics.
    for row in out['lines']:
        ll, r = row['ll'], row['ro']
        if any(abs(relative(ll[k], r[k], ll['efl'] if k.endswith('pos') or k == 'bfl' else None)) > FIRST_ORDER_TOLERANCE
               for k in ('efl', 'bfl', 'enp_pos', 'enp_d', 'exp_pos', 'exp_d')):
            same = load_rayoptics(path)
            same['seq_model'].stop_surface = stop
            set_line(same, row['nm'])
            with_lenslab_indices(same, lenslab[row['line']]['surfaces'])
            fill_stop(same, stop, row['stop_d'] / 2)
            row['ro_ll_index'] = rayoptics_first_order(same)
    out['glass_notes'] = glass_notes(opm, lenslab)
    if with_spots:
        out['spots'] = spots(path, binary, paraxial_flag, opm, stop, lenslab['d'])
    return out


def spots(path, binary, paraxial_flag, opm, stop, lens_d):
    nm = LINES[1][1]
    args = ['analyze', path, '--fields', '0,1', '--wavelengths', 'd']
    if paraxial_flag:
        args += ['--image-plane', 'paraxial']
    an, err = lenslab_json(binary, args)
    if err is not None:
        return {'refused': 'lenslab analyze: ' + err}
    set_line(opm, nm)
    stop_r = lens_d['stop']['diameter'] / 2
    fill_stop(opm, stop, stop_r)
    rear = lens_d['surfaces'][-1]['z']
    plane_ll = rear - an['image_z']                  # lenslab's image plane, from the last surface
    plane_parax_ll = rear - lens_d['F_prime']['z']   # lenslab's paraxial focus (d, infinity)
    result = {'largest': an['largest_field_deg'], 'image_z': an['image_z'], 'fields': []}
    for f in an['fields']:
        deg = f['field_deg']
        row = {'deg': deg, 'll': f['spots'][0]['rms_radius_mm'], 'll_passed': f['spots'][0]['rays_passed']}
        try:
            aimer = Aimer(opm, stop, deg, nm)
        except (RuntimeError, ro.TraceError, np.linalg.LinAlgError) as e:
            row['error'] = f'ray-optics: no chief ray ({e})'
            result['fields'].append(row)
            continue
        if deg == 0:
            result['parax_s_ro'] = paraxial_image_s(aimer, stop_r)
            result['parax_s_ll'] = plane_parax_ll
        row['hex_ll_plane'], row['hex_passed'] = rms_spot(aimer, stop_r, plane_ll, hexapolar())
        row['gauss_ll_plane'], _, _ = converged_rms(aimer, stop_r, plane_ll)
        row['gauss_parax'], row['gauss_count'], row['gauss_n'] = converged_rms(aimer, stop_r, result['parax_s_ro'])
        result['fields'].append(row)
    # ray-optics' own aiming of the chief ray at the largest field, last: it changes the field spec.
    if an['largest_field_deg'] > 0:
        try:
            result['ro_chief_miss'] = rayoptics_chief_miss(opm, stop, an['largest_field_deg'], nm)
            result['stop_r'] = stop_r
        except Exception as e:
            result['ro_chief_miss_error'] = f'{type(e).__name__}: {e}'
    return result


# ---------------------------------------------------------------------------------------------
# the table


def fmt(v, digits=6):
    return '-' if v is None or (isinstance(v, float) and not math.isfinite(v)) else f'{v:.{digits}g}'


def flag(rel, tol):
    return f'{rel:+.1e}' + (' **X**' if abs(rel) > tol else '')


def first_order_table(results):
    lines = ['| prescription | line | EFL | ΔEFL | BFL | ΔBFL | EnP pos | Δ | EnP D | Δ | ExP pos | Δ | ExP D | Δ | '
             'lenslab f/ (real) | ray-optics f/ (real) | Δ | ray-optics f/ (parax.) | Δ (lenslab EFL/EPD) | max Δn |',
             '|' + '---|' * 20]
    for r in results:
        name = os.path.relpath(r['file'], REPO) if r['file'].startswith(REPO) else os.path.basename(r['file'])
        if 'refused' in r:
            lines.append(f'| {name} | | {r["refused"].replace("|", "/")} |' + ' |' * 17)
            continue
        for row in r['lines']:
            ll, ro_ = row['ll'], row['ro']
            cells = [name, row['line'], fmt(ll['efl'], 8), flag(relative(ll['efl'], ro_['efl']), FIRST_ORDER_TOLERANCE)]
            for k in ('bfl', 'enp_pos', 'enp_d', 'exp_pos', 'exp_d'):
                scale = ll['efl'] if k.endswith('pos') or k == 'bfl' else None
                cells += [fmt(ll[k], 7), flag(relative(ll[k], ro_[k], scale), FIRST_ORDER_TOLERANCE)]
            cells += [fmt(ll['fstop'], 6), fmt(ro_['fstop'], 6), flag(relative(ll['fstop'], ro_['fstop']), FIRST_ORDER_TOLERANCE),
                      fmt(ro_['fno'], 6), flag(relative(ll['fno'], ro_['fno']), FIRST_ORDER_TOLERANCE),
                      f'{row["dn"]:.1e}']
            lines.append('| ' + ' | '.join(cells) + ' |')
    return '\n'.join(lines)


def spot_table(results):
    lines = ['| prescription | field (deg): largest in lenslab (in the file) | lenslab analyze RMS (um) | ray-optics hex10, same plane (um) | Δ | '
             'ray-optics area-uniform, same plane (um) | ray-optics area-uniform, paraxial plane (um) | sampling (r x azimuth) | '
             'ray-optics chief ray at the stop (mm off centre / stop radius) |',
             '|' + '---|' * 9]
    for r in results:
        if 'refused' in r:
            continue
        name = os.path.relpath(r['file'], REPO) if r['file'].startswith(REPO) else os.path.basename(r['file'])
        s = r['spots']
        if 'refused' in s:
            lines.append(f'| {name} | | {s["refused"]} |' + ' |' * 6)
            continue
        for row in s['fields']:
            if 'error' in row:
                lines.append(f'| {name} | {row["deg"]:.4g} | {row["ll"] * 1e3:.4g} | {row["error"]} |' + ' |' * 5)
                continue
            miss, field = '', f'{row["deg"]:.4g}'
            if row['deg'] > 0 and 'file_field' in r:
                field += f' (file: {r["file_field"]:.4g}, {r["file_field_key"]})'
            if row['deg'] > 0 and 'ro_chief_miss' in s:
                miss = f'{s["ro_chief_miss"]:.4g} / {s["stop_r"]:.4g}'
            lines.append('| ' + ' | '.join([
                name, field, f'{row["ll"] * 1e3:.4g} ({row["ll_passed"]} rays)', f'{row["hex_ll_plane"] * 1e3:.4g}',
                flag(relative(row['ll'], row['hex_ll_plane']), SPOT_TOLERANCE), f'{row["gauss_ll_plane"] * 1e3:.4g}',
                f'{row["gauss_parax"] * 1e3:.4g}', f'{row["gauss_n"]}, {row["gauss_count"]} pass', miss]) + ' |')
    return '\n'.join(lines)


def default_files():
    shared = os.path.normpath(os.path.join(REPO, '..', 'shared', 'realworld', 'prescriptions'))
    found = []
    for pattern in ('*.zmx', '*.seq', '*.dat'):
        found += sorted(glob.glob(os.path.join(shared, pattern)))
    for pattern in ('*.dat', '*.zmx'):
        found += sorted(glob.glob(os.path.join(REPO, 'lenses', pattern)))
    # The public folder holds copies of four bundled tables: each content once.
    seen, unique = set(), []
    for path in found:
        with open(path, 'rb') as f:
            content = f.read()
        if content not in seen:
            seen.add(content)
            unique.append(path)
    return unique


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('files', nargs='*', help='prescriptions (default: the public ones and the bundled lenses)')
    ap.add_argument('--lenslab', default=os.path.join(REPO, 'build', 'cli', 'lenslab'))
    ap.add_argument('--json', help='also write every number to this file')
    ap.add_argument('--jobs', type=int, default=1, help='prescriptions compared at once (processes)')
    ap.add_argument('--no-spots', action='store_true', help='first order only (seconds instead of minutes a lens)')
    ap.add_argument('--from-json', help='print the tables of a run saved with --json, running nothing')
    args = ap.parse_args()
    if args.from_json:
        with open(args.from_json) as f:
            saved = json.load(f)
        print_tables(saved['header'], saved['results'], spots=any('spots' in r for r in saved['results']))
        return
    refuse_network()
    import_rayoptics()
    paraxial_flag = analyze_has_image_plane(args.lenslab)
    jobs = [(os.path.abspath(p), os.path.abspath(args.lenslab), paraxial_flag, not args.no_spots)
            for p in args.files or default_files()]
    header = (f'Run {datetime.date.today()}: ray-optics {source_commit("rayoptics")}, opticalglass '
              f'{source_commit("opticalglass")}; lenslab analyze '
              + ('with --image-plane paraxial' if paraxial_flag else 'on its own image plane (no --image-plane yet)') + '.')
    import multiprocessing
    results = []
    with multiprocessing.Pool(args.jobs) as pool:
        for r in pool.imap(compare_in_worker, jobs, chunksize=1):
            results.append(r)
            if args.json:   # kept up to date: a long run can be read while it goes on
                with open(args.json, 'w') as f:
                    json.dump({'header': header, 'results': results}, f, indent=1, default=float)
    print_tables(header, results, spots=not args.no_spots)


def print_tables(header, results, spots):
    print(header + '\n')
    print('### First order (Δ: (lenslab - ray-optics) / |ray-optics|; positions and BFL / EFL)\n')
    print(first_order_table(results))
    if spots:
        print('\n### RMS spot radius, d line (Δ: lenslab against ray-optics with the same rays)\n')
        print(spot_table(results))
    print('\n### Notes\n')
    for r in results:
        for n in r.get('notes', []) + r.get('glass_notes', []):
            print(f'- {os.path.basename(r["file"])}: {n}')
        for row in r.get('lines', []):
            if 'ro_ll_index' in row:
                d = {k: relative(row['ll'][k], row['ro_ll_index'][k], row['ll']['efl'] if k.endswith('pos') or k == 'bfl' else None)
                     for k in ('efl', 'bfl', 'enp_pos', 'enp_d', 'exp_pos', 'exp_d')}
                print(f'- {os.path.basename(r["file"])} {row["line"]}: with lenslab\'s indices in ray-optics: '
                      + ', '.join(f'{k} {v:+.1e}' for k, v in d.items()))


if __name__ == '__main__':
    main()
