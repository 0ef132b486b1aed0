#!/usr/bin/python3
"""lenslab against ray-optics, an independent lens design program (issues 28 and 29).

For every prescription lenslab reads among the public ones (../shared/realworld/prescriptions:
*.zmx, *.seq, *.dat) and the bundled lenses (lenses/*.dat, *.zmx), at the F, d and C lines (or
at the file's own wavelengths where they all lie outside 380-780 nm: the 248 nm and 1550 nm
lenses): EFL, BFL, entrance and exit pupil positions and diameters and the f-number; and at the
d line (those lenses: their primary wavelength) the RMS spot radius on axis and at lenslab's
largest field. Prints Markdown tables and, below them, the notes they refer to. A file lenslab
or ray-optics refuses is listed with its message.

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
- lenslab: `lenslab lens FILE --json [--wavelength NM]` at each line (its widest aperture, focus
  at infinity), and `lenslab analyze FILE --json --fields 0,1 --wavelengths d --wavelength d
  --image-plane paraxial` (on axis and at its largest field, the d line made the primary so that
  the paraxial plane is its F'); its spots are area-uniform over the stop (docs/analysis.md).
- ray-optics: its own reader for .zmx and .seq (.seq in inches or cm scaled to mm); a .dat table
  (which it cannot read) is built here into ray-optics' sequential model. Where its reader gets an
  aperture wrong or leaves it out (fix_zemax_apertures), it is set as the file says, and where
  lenslab derives an aperture itself (a Code V surface without CIR) ray-optics' is opened as
  lenslab's is (docs/prescriptions.md: it clips nothing). Its aperture is set from lenslab's stop
  opening at that line: the entrance pupil diameter that fills the stop paraxially. Positions:
  entrance pupil from the front vertex, exit pupil from the rear vertex, BFL from the rear vertex
  to F', all positive in the direction light travels there; ray-optics' EFL carries n' (negative
  after an odd number of mirrors) and is taken with lenslab's sign.
- Decentred or tilted lenses: ray-optics' paraxial trace leaves decentres and tilts out, so first
  order is taken along the axis ray (the zero field's ray through the stop's centre, as lenslab
  measures it) with ray-optics' real trace, by differences of rays 1e-5 of the pupil off it: EFL
  (y section; x in the notes), BFL from the foot of the last vertex, the entrance pupil's x section
  (y in the notes). The decentres and tilts each program read are compared surface by surface.
- f-number: lenslab's is 1 / (2 sin theta') of the real marginal ray at F' (README, Conventions);
  the script finds the same ray with ray-optics' trace (the meridional ray through the stop's rim
  and ray-optics' paraxial F') and compares. The paraxial f-number, EFL / EPD, is compared too.
- A first-order difference over the tolerance is looked into by the script: ray-optics is run again
  with lenslab's index of every medium at that line (a difference that vanishes then lies in the
  glass data), and every medium whose indices differ by over 1e-5 is listed with both programs'
  indices and the Abbe number they imply, Vd = (nd - 1) / (nF - nC), against the file's Vd.
- Spots: rays are aimed by this script with ray-optics' real trace at points of the stop (Newton
  on the ray's start, apertures ignored while aiming, then traced with ray-optics' aperture
  checks; ray-optics' own chief-ray aiming is wrong off axis, and the table lists how far its chief
  ray misses the stop's centre), cut with the plane across the axis ray at ray-optics' own F', and
  integrated area-uniformly over the passing part of the stop (PupilIntegral); RMS about the
  weighted centroid. A spot over the tolerance is run again with lenslab's indices and with
  lenslab's clear radii.
"""
import argparse
import contextlib
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
SPOT_FLOOR_MM = 1e-6           # both spots under 1 nm: rounding, not a spot (a perfect paraboloid's)
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
    from rayoptics.elem.surface import Circular, Rectangular, Surface
    from rayoptics.seq.gap import Gap
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
    try:
        with contextlib.redirect_stdout(sys.stderr):   # ray-optics prints its aiming failures
            return compare(*job)
    except Exception as e:   # one lens's failure is reported in its row, not the run's end
        import traceback
        traceback.print_exc()
        return {'file': job[0], 'notes': [], 'refused': f'compare_rayoptics failed: {type(e).__name__}: {e}'}


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
    """The apertures ray-optics' .zmx reader gets wrong or leaves out at this commit, set as the
    file says (read here from the file, not from lenslab):
    - `DIAM r 0 ...` (a semi-diameter Zemax solved for) counts for ray-optics as no aperture, and it
      then sizes every aperture itself from its own rays: each is set to the file's r;
    - `DIAM r 2 s ...` is a semi-diameter picked up from surface s (the second field is the
      semi-diameter's solve type), which ray-optics takes for aperture type 2, an obscuration;
    - `CLAP 0 r` (a circular aperture, which overrides DIAM), `SQAP xh yh` (a rectangle) and
      `OBSC rmin rmax` (a central obscuration) are not read at all.
    Returns what was changed."""
    changed = []
    sm = opm['seq_model']
    for n, lines in zemax_surface_lines(path).items():
        if not 0 < n < len(sm.ifcs) - 1 or getattr(sm.ifcs[n], 'z_type', None) == 'COORDBRK':
            continue
        ifc = sm.ifcs[n]
        words_of = {w[0]: w for w in lines}
        clear = [ca for ca in ifc.clear_apertures if not ca.is_obscuration]
        if 'SQAP' in words_of:
            w = words_of['SQAP']
            rect = ro.Rectangular(x_half_width=float(w[1]), y_half_width=float(w[2]))
            if clear:   # OBDC's decentre, which ray-optics put on the circle it read
                rect.x_offset, rect.y_offset = clear[0].x_offset, clear[0].y_offset
            ifc.clear_apertures = [rect] + [ca for ca in ifc.clear_apertures if ca.is_obscuration]
            changed.append(f'surface {n}: SQAP {w[1]} {w[2]} added (ray-optics ignores SQAP)')
        elif 'CLAP' in words_of and float(words_of['CLAP'][2]) > 0:
            r = float(words_of['CLAP'][2])
            ifc.clear_apertures = [ro.Circular(radius=r)] + [ca for ca in ifc.clear_apertures if ca.is_obscuration]
            changed.append(f'surface {n}: CLAP {r} added (ray-optics ignores CLAP)')
        elif 'DIAM' in words_of and len(words_of['DIAM']) > 2:
            w = words_of['DIAM']
            r = float(w[1])
            if w[2] == '2':
                for ca in ifc.clear_apertures:
                    if ca.is_obscuration:
                        ca.is_obscuration = False
                        changed.append(f'surface {n}: DIAM pickup read as an obscuration, made the clear aperture')
            elif r > 0:
                if clear:
                    clear[0].radius = r
                else:
                    ifc.clear_apertures.insert(0, ro.Circular(radius=r))
                ifc.set_max_aperture(r)
                changed.append(f'surface {n}: the file\'s DIAM {r} kept (ray-optics resizes a solved one)')
        if 'OBSC' in words_of and len(words_of['OBSC']) > 2 and float(words_of['OBSC'][2]) > 0:
            r = float(words_of['OBSC'][2])
            ifc.clear_apertures.append(ro.Circular(radius=r, is_obscuration=True))
            changed.append(f'surface {n}: OBSC {r} added (ray-optics ignores OBSC)')
    sm.do_apertures = False   # the file's apertures, not ray-optics' own sizing
    opm.update_model()
    return changed


MM_PER_UNIT = {'mm': 1.0, 'cm': 10.0, 'inches': 25.4}


def load_rayoptics(path, notes=None):
    if path.endswith('.dat'):
        return build_table_model(path)
    opm = ro.open_model(path)
    if path.endswith('.zmx'):
        changed = fix_zemax_apertures(opm, path)
        if notes is not None:
            notes.extend(changed)
    # ray-optics keeps a file's own unit (Code V DIM I, C); lenslab works in mm.
    unit = opm['system_spec'].dimensions
    if MM_PER_UNIT[unit] != 1.0:
        opm.apply_scale_factor(MM_PER_UNIT[unit])
        opm['system_spec'].dimensions = 'mm'
        if notes is not None:
            notes.append(f'the file is in {unit}: ray-optics\' model scaled by {MM_PER_UNIT[unit]} to mm')
    return opm


def lens_surfaces(sm):
    """The ray-optics interfaces that are lenslab's surfaces, in order: every one between object
    and image but Zemax's coordinate breaks, which lenslab folds into the next surface's frame."""
    return [i for i in range(1, len(sm.ifcs) - 1) if getattr(sm.ifcs[i], 'z_type', None) != 'COORDBRK']


def trailing_dummy(sm, idx, surfaces):
    """A Code V file without SI (test.seq): ray-optics makes its last S the image, lenslab reads it
    as a surface (a flat between air and air) and puts the image on it. Where that is the one
    difference, the flat is added to ray-optics' model before its image, on the image."""
    last = surfaces[-1]
    if len(idx) != len(surfaces) - 1 or last['radius'] != 0 or last['n'] != surfaces[-2]['n'] or last['mirror']:
        return False
    sm.cur_surface = len(sm.ifcs) - 2
    s, g = ro.Surface(), ro.Gap()
    g.thi, g.medium = 0.0, sm.gaps[-1].medium
    sm.insert(s, g)
    sm.ifcs[-1].label = 'Img'
    sm.opt_model.update_model()
    return True


def last_working_surface(sm, nm):
    """The last surface that bends the light (a mirror, or a change of index): the rays leaving it
    are the image space's, and a flat dummy after it (CODV_35571's last surface is tilted 90 degrees,
    along the rays) would only give its hit points less precisely."""
    for k in reversed(lens_surfaces(sm)):
        ifc = sm.ifcs[k]
        if (ifc.interact_mode == 'reflect' or ifc.profile.cv != 0
                or sm.gaps[k - 1].medium.rindex(nm) != sm.gaps[k].medium.rindex(nm)):
            return k
    return lens_surfaces(sm)[-1]


def media_gaps(sm, idx, k):
    """The gaps that hold the medium after lenslab's surface k (a coordinate break after a surface
    splits its gap)."""
    end = idx[k + 1] if k + 1 < len(idx) else len(sm.ifcs) - 1
    return [sm.gaps[g] for g in range(idx[k], end)]


def match_apertures(sm, idx, surfaces):
    """Where lenslab derives a surface's aperture itself (a Code V surface without CIR, a .zmx
    DIAM 0), it clips nothing (docs/prescriptions.md, Automatic apertures): ray-optics' own
    automatic apertures are opened likewise, so that the stop alone limits the bundle there."""
    opened = []
    for k, s in zip(idx, surfaces):
        if s.get('automatic_aperture') and not s['is_stop']:
            # its obscurations stay (questar35's secondary)
            kept = [ca for ca in sm.ifcs[k].clear_apertures if ca.is_obscuration]
            sm.ifcs[k].clear_apertures = [ro.Circular(radius=1e9)] + kept
            sm.ifcs[k].max_aperture = 1e9
            opened.append(k)
    if opened:
        sm.do_apertures = False
    return opened


def set_line(opm, nm):
    """ray-optics' reference wavelength set to nm (its spectrum: F, d, C and nm)."""
    osp = opm['optical_spec']
    wvls = sorted({w for _, w in LINES} | {nm})
    osp['wvls'] = ro.WvlSpec([(w, 1.0) for w in wvls], ref_wl=wvls.index(nm))
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
    """ray-optics' paraxial figures in lenslab's conventions. ray-optics' EFL is n'/power, so after an
    odd number of mirrors (n' = -1) it is negative for a converging system: it is taken as
    sign(n') n'/power. Its paraxial slopes run along the light (a mirror's turn is in n'), so the
    exit pupil's distance along the light is -height/slope of the chief ray leaving the last surface,
    while its BFL is along its local z (z_dir says which way the light runs there)."""
    pd = opm['analysis_results']['parax_data']
    fod, pr = pd.fod, pd.pr_ray
    sm = opm['seq_model']
    last = lens_surfaces(sm)[-1]
    exp = -pr[last][0] / pr[last][1]
    efl = fod.efl * math.copysign(1.0, fod.n_img)
    # The paraxial f-number for an object at infinity, EFL / EPD (ray-optics' own fno is the
    # working f-number of the file's conjugates).
    return {'efl': efl, 'bfl': fod.bfl * sm.z_dir[last], 'enp_pos': fod.enp_dist, 'enp_d': 2 * fod.enp_radius,
            'exp_pos': exp, 'exp_d': 2 * fod.exp_radius, 'fno': abs(efl) / (2 * fod.enp_radius)}


def lenslab_first_order(j):
    """lenslab's figures; where it gives first order only (`incomplete`: no aperture or focus at
    this wavelength), the pupils and f-number are None."""
    s = j['surfaces']
    front, rear = s[0]['z'], s[-1]['z']
    # lens z runs toward the scene; light leaves the last surface toward -z unless an odd
    # number of mirrors turned it.
    out_dir = -1 if sum(1 for x in s if x['mirror']) % 2 == 0 else 1
    out = {'efl': j['efl'], 'bfl': j['back_focal_distance'], 'enp_pos': None, 'enp_d': None, 'exp_pos': None,
           'exp_d': None, 'fno': None, 'fstop': None}
    if 'entrance_pupil' in j:
        out.update({'enp_pos': front - j['entrance_pupil']['z'], 'enp_d': j['entrance_pupil']['diameter'],
                    'exp_pos': (j['exit_pupil']['z'] - rear) * out_dir, 'exp_d': j['exit_pupil']['diameter'],
                    'fno': j['efl'] / j['entrance_pupil']['diameter'], 'fstop': j['fstop']})
    return out


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

    def __init__(self, opm, stop_index, field_deg, nm, guess=None):
        self.sm, self.nm, self.stop = opm['seq_model'], nm, stop_index
        self.last = last_working_surface(self.sm, nm)
        fod = opm['analysis_results']['parax_data'].fod
        t = math.radians(field_deg)
        self.dir = np.array([0.0, -math.sin(t), math.cos(t)])   # lenslab's sign: toward -y
        self.z_aim = fod.obj_dist + fod.enp_dist
        self.z_start = fod.obj_dist - 1000.0 - 2 * abs(fod.enp_dist)
        self.scale = fod.enp_radius
        self.jac = None
        try:
            self.chief = self.aim(np.zeros(2), guess=guess)
        except (RuntimeError, ro.TraceError, np.linalg.LinAlgError):
            self.jac = None
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

    def exit(self, a, **kwargs):
        """The ray from start a as it leaves the last surface: point and direction, in that
        surface's coordinates."""
        ray = self.trace(a, **kwargs)
        return np.array(ray[self.last][0]), np.array(ray[self.last][1])

    def image_point(self, a, plane):
        """Where the ray from start a meets the image plane (a point on it and its normal, in the
        last surface's coordinates), in two coordinates across the normal, or None when an aperture
        blocks it."""
        try:
            p, d = self.exit(a, check_apertures=True)
        except ro.TraceError:
            return None
        o, nrm = plane
        t = ((o - p) @ nrm) / (d @ nrm)
        q = p + t * d - o
        ex = np.array([1.0, 0.0, 0.0]) - nrm[0] * nrm
        ex /= np.linalg.norm(ex)
        return np.array([q @ ex, q @ np.cross(nrm, ex)])


def rms_about_centroid(sums):
    w, sx, sy, sq = sums
    return math.sqrt(max(sq / w - (sx / w) ** 2 - (sy / w) ** 2, 0.0))


class PupilIntegral:
    """The area-uniform RMS spot radius of one field on one image plane, with ray-optics' trace:
    the stop (radius R) is swept by lines from a point c inside the passing part of it (the
    centroid of the passing points of an 11 x 11 grid), at equally spaced azimuths; along each
    line the stretches whose rays reach the image are found by a scan of 16 points and bisection
    of each change (to 1e-7 R), and each stretch is integrated by 8 Gauss-Legendre nodes in u = t^2
    (the area element t dt dphi = du dphi / 2). The azimuths double from 16 until the RMS moves by
    <= 0.2 %, or 256. Written for this comparison from the definition, not after lenslab's code."""

    def __init__(self, aimer, stop_r, plane):
        self.aimer, self.R, self.plane = aimer, stop_r, plane
        self.guess = aimer.chief
        self.gl = np.polynomial.legendre.leggauss(8)
        self.rays = 0

    def point(self, xy):
        """The ray through stop point xy on the image plane (2 coordinates), or None."""
        self.rays += 1
        try:
            a = self.aimer.aim(np.asarray(xy, dtype=float), guess=self.guess)
        except (RuntimeError, ro.TraceError, np.linalg.LinAlgError):
            try:
                self.aimer.jac = None
                a = self.aimer.aim(np.asarray(xy, dtype=float), guess=self.aimer.chief)
            except (RuntimeError, ro.TraceError, np.linalg.LinAlgError):
                return None
        q = self.aimer.image_point(a, self.plane)
        if q is not None:
            self.guess = a
        return q

    def centre(self):
        g = np.linspace(-1, 1, 11) * self.R
        inside = [(x, y) for x in g for y in g if x * x + y * y <= self.R * self.R * (1 - 1e-9)]
        passing = np.array([p for p in inside if self.point(p) is not None])
        if not len(passing):
            return None
        return passing.mean(0)

    def line_sums(self, c, phi):
        u = np.array([math.sin(phi), math.cos(phi)])
        cu = c @ u
        T = -cu + math.sqrt(cu * cu - c @ c + self.R * self.R)   # to the stop's rim
        scan = [(k + 0.5) / 16 * T for k in range(16)]
        passes = [self.point(c + t * u) is not None for t in scan]

        def edge(t_pass, t_block):
            for _ in range(24):
                m = (t_pass + t_block) / 2
                if self.point(c + m * u) is not None:
                    t_pass = m
                else:
                    t_block = m
            return (t_pass + t_block) / 2

        stretches, start = [], None
        at_c = self.point(c) is not None
        prev_t, prev_pass = 0.0, at_c
        for t, ok in zip(scan, passes):
            if ok and not prev_pass:
                start = edge(t, prev_t)
            elif ok and start is None:
                start = 0.0
            if not ok and prev_pass and start is not None:
                stretches.append((start, edge(prev_t, t)))
                start = None
            prev_t, prev_pass = t, ok
        if start is not None:
            stretches.append((start, T))
        sums = np.zeros(4)
        x, w = self.gl
        for a, b in stretches:
            for xi, wi in zip(x, w):
                t = math.sqrt(a * a + (b * b - a * a) * (xi + 1) / 2)
                q = self.point(c + t * u)
                if q is None:   # a sliver the scan missed
                    continue
                ww = wi * (b * b - a * a)
                sums += ww * np.array([1.0, q[0], q[1], q @ q])
        return sums

    def rms(self):
        """(RMS radius, azimuths used, last change on doubling, rays traced, share of the stop's area
        whose rays arrive), or (nan, ...)."""
        c = self.centre()
        if c is None:
            return float('nan'), 0, float('nan'), self.rays, 0.0
        n, total = 16, np.zeros(4)
        for k in range(n):
            total += self.line_sums(c, 2 * math.pi * k / n)
        prev = rms_about_centroid(total) if total[0] > 0 else float('nan')
        while True:
            for k in range(n):
                total += self.line_sums(c, 2 * math.pi * (k + 0.5) / n)
            n *= 2
            cur = rms_about_centroid(total)
            change = abs(cur - prev) / cur if cur > 0 else 0.0
            if change <= 0.002 or n >= 256:
                # each line's weights sum to 2 (b^2 - a^2); the area is (1/2) sum (b^2 - a^2) 2 pi / n
                return cur, n, change, self.rays, total[0] / (2 * n * self.R * self.R)
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


def paraxial_entrance_d(aimer, stop_r, e):
    """The entrance pupil's diameter along the axis ray in the section e (a unit vector across the
    stop): the stop's diameter times the spread of the incoming rays that cross the stop at +-1e-4
    of its radius over their spread there. Every tilt in these files is about x: the x section is
    square to them."""
    e = 1e-4 * stop_r * np.asarray(e, dtype=float)
    up, down = aimer.aim(e, guess=aimer.chief), aimer.aim(-e, guess=aimer.chief)
    return float(np.linalg.norm(up - down) / 1e-4)


def nominal_vertex(ifc):
    """The vertex the coordinates after a surface are measured from, in its local coordinates: a
    decentre-and-return surface returns them to where its vertex was before its own decentre d and
    rotation R (-R^T d); after any other the coordinates follow the surface (its local origin)."""
    dec = ifc.decenter
    if dec is None or dec.dtype != 'dec and return':
        return np.zeros(3)
    return -dec.rot_mat.T @ dec.dec


def vertex_bfl(aimer, axis, k):
    """BFL as lenslab measures it along the axis ray (trace/AxisRay.h: the image space is turned
    about the last vertex): from the foot of surface k's nominal vertex on the axis ray to F'."""
    ray = aimer.trace(aimer.chief)
    path = sum(ray[j][2] for j in range(aimer.last, k))   # from the last surface that bends the light
    p, d = np.array(ray[k][0]), np.array(ray[k][1])
    return axis['bfl_y'] - path + float((p - nominal_vertex(aimer.sm.ifcs[k])) @ d)


def axis_ray_first_order(aimer):
    """First order along the axis ray with ray-optics' real trace (docs/prescriptions.md: lenslab
    measures a decentred or tilted lens along the zero field's ray through the stop's centre):
    rays parallel to it at +-h (1e-5 of the entrance pupil radius) in y and in x, and where
    they leave the last surface against it. EFL = h / tan of the angle they make with the axis
    ray there (central differences), positive where they converge on it; BFL: from the axis
    ray's point on the last surface that bends the light, along it, to where the y rays cross it (F'). Returns the
    figures and the plane across the axis ray at F' (point, normal, in the last surface's
    coordinates) for the spots."""
    p0, d0 = aimer.exit(aimer.chief)
    # the two sections across the axis ray as it leaves (every tilt in these files is about x)
    vx = np.array([1.0, 0.0, 0.0]) - d0[0] * d0
    vx /= np.linalg.norm(vx)
    sections = {'y': (np.array([0.0, 1.0]), np.cross(d0, vx)), 'x': (np.array([1.0, 0.0]), vx)}
    out = {}
    h = 1e-5 * aimer.scale
    for name, (e, v) in sections.items():
        efls, ts = [], []
        for sgn in (1, -1):
            p1, d1 = aimer.exit(aimer.chief + sgn * h * e)
            q = (p1 - p0) - ((p1 - p0) @ d0) * d0        # its height off the axis ray
            slope = (d1 @ v) / (d1 @ d0)
            # h over the angle it makes with the axis ray, signed so that a ray that keeps the side
            # of the axis ray it entered on and turns toward it makes a positive EFL
            efls.append(-sgn * h * math.copysign(1.0, (q @ v) * sgn) / slope)
            ts.append(((p1 - p0) @ d0) - (q @ v) / slope)   # along the axis ray to its crossing
        out['efl_' + name] = float(np.mean(efls))
        out['bfl_' + name] = float(np.mean(ts))
    out['plane'] = (p0 + out['bfl_y'] * d0, d0)
    return out


# ---------------------------------------------------------------------------------------------
# one prescription


def relative(a, b, scale=None):
    return (a - b) / abs(scale if scale is not None else b)


def with_lenslab_indices(opm, idx, surfaces):
    """ray-optics' model with every medium replaced by lenslab's index at the current line."""
    sm = opm['seq_model']
    for k, s in enumerate(surfaces):
        for g in media_gaps(sm, idx, k):
            g.medium = ro.ConstantIndex(abs(s['n']), 'lenslab')
    opm.update_model()


def prepared_model(path, surfaces, stop, nm, stop_r, indices=False, apertures=False):
    """ray-optics' model of the file, prepared as for the comparison; with `indices`, lenslab's index
    of every medium at nm (a difference that vanishes then lies in the glass data); with
    `apertures`, lenslab's clear radius on every circular aperture that lenslab does not derive
    itself (where it differs from the file's: lenslab clips a lens where its two surfaces cross
    inside the clear aperture, and warns). Returns the model and the apertures changed."""
    same = load_rayoptics(path)
    sm = same['seq_model']
    trailing_dummy(sm, lens_surfaces(sm), surfaces)
    idx = lens_surfaces(sm)
    match_apertures(sm, idx, surfaces)
    sm.stop_surface = stop
    set_line(same, nm)
    if indices:
        with_lenslab_indices(same, idx, surfaces)
    changed = []
    if apertures:
        for k, x in zip(idx, surfaces):
            if x.get('automatic_aperture') or 'clear_aperture' in x:
                continue
            for ca in sm.ifcs[k].clear_apertures:
                if not ca.is_obscuration and isinstance(ca, ro.Circular) and abs(ca.radius - x['diameter'] / 2) > 1e-9:
                    changed.append(f'surface {k}: {ca.radius:.6g} -> {x["diameter"] / 2:.6g}')
                    ca.radius = x['diameter'] / 2
        same.update_model()
    fill_stop(same, stop, stop_r)
    return same, changed


def rerun_spot(path, surfaces, stop, nm, stop_r, deg, chief, **which):
    """The spot again on a prepared model (prepared_model's options; its chief ray sought from the
    first model's, `chief`), or an error."""
    try:
        same, changed = prepared_model(path, surfaces, stop, nm, stop_r, **which)
        if which.get('apertures') and not changed:
            return None, None
        axis = axis_ray_first_order(Aimer(same, stop, 0.0, nm))
        return PupilIntegral(Aimer(same, stop, deg, nm, guess=chief), stop_r, axis['plane']).rms()[0], changed
    except (RuntimeError, ro.TraceError, np.linalg.LinAlgError) as e:
        return None, f'no chief ray ({type(e).__name__})'


def abbe(n):
    return (n[1] - 1) / (n[0] - n[2]) if len(n) == 3 and n[0] != n[2] else float('nan')


def glass_notes(opm, idx, lenslab, lines):
    """The media whose indices differ by more than 1e-5 at a line: what each program takes, and
    the closed-form check Vd = (nd - 1) / (nF - nC) against the Vd the file states (ray-optics'
    reading of it, for a model glass)."""
    sm, notes = opm['seq_model'], []
    first = lines[0][0]
    for k, s in enumerate(lenslab[first]['surfaces']):
        m = sm.gaps[idx[k]].medium
        n_ll = [abs(lenslab[name]['surfaces'][k]['n']) for name, _ in lines]
        n_ro = [m.rindex(nm) for _, nm in lines]
        if max(abs(a - b) for a, b in zip(n_ll, n_ro)) <= 1e-5:
            continue
        stated = f', the file\'s Vd {m.v:.4g}' if hasattr(m, 'v') else ''
        at = ' '.join(name for name, _ in lines)
        note = (f'{s["glass"] or "model"}{" " + s["catalog"] if s["catalog"] else ""}: lenslab n at {at} '
                + ' '.join(f'{v:.6f}' for v in n_ll) + f' (Vd {abbe(n_ll):.4g}); ray-optics {type(m).__name__} '
                f'{m.name()}: ' + ' '.join(f'{v:.6f}' for v in n_ro) + f' (Vd {abbe(n_ro):.4g}){stated}')
        if note not in notes:
            notes.append(note)
    return notes


FRAME_MODES = {'basic': 'decenter', 'decentre and return': 'dec and return', 'bend': 'bend', 'reverse': 'reverse'}


def frame_notes(sm, idx, surfaces):
    """A surface's own decentre and tilt as each program read it (lenslab's `frame`, ray-optics'
    DecenterData): equal, or the difference."""
    notes = []
    for k, s in zip(idx, surfaces):
        f, d = s.get('frame'), sm.ifcs[k].decenter
        if f is None and d is None:
            continue
        if f is None or d is None:
            notes.append(f'surface {k}: decentre in {"ray-optics" if f is None else "lenslab"} only')
            continue
        same = (FRAME_MODES[f['mode']] == d.dtype and np.allclose(f['decentre'], d.dec, atol=1e-9)
                and np.allclose(f['tilt_degrees'], d.euler, atol=1e-9))
        if not same:
            notes.append(f'surface {k}: lenslab {f["mode"]} {f["decentre"]} {f["tilt_degrees"]} deg; '
                         f'ray-optics {d.dtype} {list(d.dec)} {list(d.euler)} deg')
    return notes


def analysis_lines(lens):
    """F, d, C; or, for a lens designed wholly outside the visible (the 248 nm and 1550 nm
    lenses, whose glass data may not reach the d line), the file's own wavelengths."""
    own = lens['design']['wavelengths_nm']
    if own and all(nm < 380 or nm > 780 for nm in own):
        return [(f'{nm:g} nm', nm) for nm in own]
    return list(LINES)


def lenslab_at(binary, path, nm, lens):
    """`lenslab lens` at one wavelength (the primary without --wavelength: its range is 360-830 nm)."""
    args = ['lens', path] if nm == lens['primary_wavelength_nm'] else ['lens', path, '--wavelength', repr(nm)]
    return lenslab_json(binary, args)


def compare(path, binary, paraxial_flag, with_spots=True):
    """A dict: 'refused' (who and why), or 'lines' (first order per line) and 'spots'."""
    out = {'file': path, 'notes': []}
    base, err = lenslab_json(binary, ['lens', path])
    if err is not None:
        out['refused'] = err.replace(os.path.dirname(path) + os.sep, '')
        return out
    lines = analysis_lines(base)
    out['line_names'] = [name for name, _ in lines]
    out['decentred'] = not base['rotationally_symmetric']
    lenslab = {}
    for name, nm in lines:
        j, err = lenslab_at(binary, path, nm, base)
        if err is not None:
            out['refused'] = f'lenslab at {name}: ' + err.replace(os.path.dirname(path) + os.sep, '')
            return out
        lenslab[name] = j
    try:
        opm = load_rayoptics(path, out['notes'])
    except Exception as e:   # ray-optics' readers raise many kinds
        out['refused'] = f'ray-optics: {type(e).__name__}: {str(e).splitlines()[0][:160]}'
        return out
    sm = opm['seq_model']
    surfaces = base['surfaces']
    idx = lens_surfaces(sm)
    if trailing_dummy(sm, idx, surfaces):
        out['notes'].append('no SI: ray-optics takes the last S for the image, lenslab for a surface before it '
                            '(a flat between air and air); the same flat added to ray-optics\' model')
        idx = lens_surfaces(sm)
    if len(idx) != len(surfaces):
        out['refused'] = f'not compared: ray-optics has {len(idx)} surfaces, lenslab {len(surfaces)}'
        return out
    out['frame_notes'] = frame_notes(sm, idx, surfaces)
    if base['afocal']:
        # No first order and no spots in lenslab; ray-optics' paraxial power should be nil too.
        set_line(opm, lines[0][1])
        out['afocal'] = {'ro_efl': opm['analysis_results']['parax_data'].fod.efl}
        return out
    opened = match_apertures(sm, idx, surfaces)
    if opened:
        out['notes'].append(f'{len(opened)} automatic apertures (lenslab clips nothing there) opened in ray-optics too')
    stop_k = next(k for k, s in enumerate(surfaces) if s['is_stop'])
    stop = idx[stop_k]
    if sm.stop_surface != stop:
        out['notes'].append(f'ray-optics had the stop at {sm.stop_surface}; set to lenslab\'s, surface {stop}')
        sm.stop_surface = stop
    if not path.endswith('.dat'):   # a table states no field
        out['file_field'] = opm['optical_spec']['fov'].max_field()[0]
        out['file_field_key'] = ' '.join(opm['optical_spec']['fov'].key)
    out['lines'] = []
    for name, nm in lines:
        j = lenslab[name]
        set_line(opm, nm)
        if 'incomplete' in j:
            out['notes'].append(f'lenslab at {name}: first order only ({j["incomplete"]})')
        # The stop's opening; where lenslab finds none at this line, its clear aperture.
        stop_r = j.get('stop', base.get('stop', {'diameter': surfaces[stop_k]['diameter']}))['diameter'] / 2
        fill_stop(opm, stop, stop_r)
        dn = max(abs(abs(s['n']) - sm.gaps[idx[k]].medium.rindex(nm)) for k, s in enumerate(j['surfaces']))
        first = rayoptics_first_order(opm)
        row = {'line': name, 'nm': nm, 'll': lenslab_first_order(j), 'dn': dn, 'stop_d': 2 * stop_r}
        if out['decentred']:
            # ray-optics' paraxial trace runs along the unfolded axis, decentres and tilts left out:
            # along the axis ray, from its real trace instead.
            row['ro_paraxial'] = first
            try:
                aimer = Aimer(opm, stop, 0.0, nm)
                ax = axis_ray_first_order(aimer)
                # compared as lenslab defines them: the BFL from the axis ray's point on the last
                # surface that bends the light, the entrance pupil in the meridional (y) section
                # (every tilt in these files is about x); the others in the notes
                first = {'efl': ax['efl_y'], 'efl_x': ax['efl_x'], 'bfl': ax['bfl_y'],
                         'bfl_vertex': vertex_bfl(aimer, ax, idx[-1]), 'enp_pos': None,
                         'enp_d': paraxial_entrance_d(aimer, stop_r, (0, 1)),
                         'enp_d_x': paraxial_entrance_d(aimer, stop_r, (1, 0)),
                         'exp_pos': None, 'exp_d': None, 'fno': None, 'fstop': None}
            except (RuntimeError, ro.TraceError, np.linalg.LinAlgError) as e:
                row['error'] = f'ray-optics: no axis ray ({e})'
                first = {k: None for k in ('efl', 'bfl', 'enp_pos', 'enp_d', 'exp_pos', 'exp_d', 'fno', 'fstop')}
        else:
            try:
                first['fstop'] = real_fstop(opm, stop, stop_r, nm)
            except (ro.TraceError, np.linalg.LinAlgError):
                first['fstop'] = float('nan')
        row['ro'] = first
        out['lines'].append(row)
    # Differences over the tolerance: ray-optics again with lenslab's indices, which tells a
    # difference in glass data from one in the optics.
    for row in out['lines']:
        if out['decentred'] or not over_tolerance(row['ll'], row['ro']):
            continue
        same, _ = prepared_model(path, lenslab[row['line']]['surfaces'], stop, row['nm'], row['stop_d'] / 2, indices=True)
        row['ro_ll_index'] = rayoptics_first_order(same)
    out['glass_notes'] = glass_notes(opm, idx, lenslab, lines)
    if with_spots:
        out['spots'] = spots(path, binary, paraxial_flag, opm, stop, lenslab, lines)
    return out


FIRST_ORDER_KEYS = ('efl', 'bfl', 'enp_pos', 'enp_d', 'exp_pos', 'exp_d')


def scaled_difference(ll, r, k):
    """lenslab against ray-optics, relative; positions and BFL relative to the EFL."""
    if r.get(k) is None or ll.get(k) is None:
        return None
    return relative(ll[k], r[k], ll['efl'] if k.endswith('pos') or k == 'bfl' else None)


def over_tolerance(ll, r):
    return any(d is not None and abs(d) > FIRST_ORDER_TOLERANCE for d in (scaled_difference(ll, r, k) for k in FIRST_ORDER_KEYS))


def spot_over_tolerance(ll, r):
    return (ll is not None and math.isfinite(r) and r > 0 and max(ll, r) >= SPOT_FLOOR_MM
            and abs(relative(ll, r)) > SPOT_TOLERANCE)


def spot_line(lens, lines):
    """The spots' wavelength: d, or the file's primary where the file lies outside the visible."""
    if lines[0][0] == 'F':
        return 'd', LINES[1][1]
    return f'{lens["primary_wavelength_nm"]:g} nm', lens['primary_wavelength_nm']


def spots(path, binary, paraxial_flag, opm, stop, lenslab, lines):
    name, nm = spot_line(lenslab[lines[0][0]], lines)
    lens = next(lenslab[n] for n, w in lines if w == nm) if name != 'd' else lenslab['d']
    # The spots' wavelength is made the primary: the paraxial plane is the primary's F'.
    args = ['analyze', path, '--fields', '0,1', '--wavelengths', 'd' if name == 'd' else repr(nm)]
    if name == 'd':
        args += ['--wavelength', repr(nm)]
    if paraxial_flag:
        args += ['--image-plane', 'paraxial']
    an, err = lenslab_json(binary, args)
    if err is not None:
        return {'refused': 'lenslab analyze: ' + err.replace(os.path.dirname(path) + os.sep, ''), 'line': name}
    set_line(opm, nm)
    stop_r = lens['stop']['diameter'] / 2
    fill_stop(opm, stop, stop_r)
    result = {'line': name, 'largest': an['largest_field_deg'], 'largest_source': an.get('largest_field_source'),
              'image_plane': an.get('image_plane'), 'fields': []}
    try:
        axis = axis_ray_first_order(Aimer(opm, stop, 0.0, nm))
    except (RuntimeError, ro.TraceError, np.linalg.LinAlgError) as e:
        return {'refused': f'ray-optics: no axis ray ({e})', 'line': name}
    result['ro_bfl'] = axis['bfl_y']
    sm = opm['seq_model']
    idx = lens_surfaces(sm)
    dn = max(abs(abs(x['n']) - sm.gaps[idx[k]].medium.rindex(nm)) for k, x in enumerate(lens['surfaces']))
    result['dn'] = dn
    for f in an['fields']:
        deg = f['field_deg']
        sp = f['spots'][0] if f.get('spots') else None
        row = {'deg': deg, 'll': sp['rms_radius_mm'] if sp else None, 'll_passed': sp['rays_passed'] if sp else 0,
               'll_sampling': sp.get('pupil_sampling') if sp else None,
               'll_transmission': sp.get('transmission') if sp else None}
        try:
            aimer = Aimer(opm, stop, deg, nm)
        except (RuntimeError, ro.TraceError, np.linalg.LinAlgError) as e:
            row['error'] = f'ray-optics: no chief ray ({e})'
            result['fields'].append(row)
            continue
        integral = PupilIntegral(aimer, stop_r, axis['plane'])
        row['ro'], row['ro_azimuths'], row['ro_change'], row['ro_rays'], row['ro_transmission'] = integral.rms()
        if spot_over_tolerance(row['ll'], row['ro']):
            # again with lenslab's indices, and with lenslab's clear radii: a difference that
            # vanishes with one of them lies in the glass data, or in the apertures
            if dn > 1e-9:
                rms, err = rerun_spot(path, lens['surfaces'], stop, nm, stop_r, deg, aimer.chief, indices=True)
                if rms is None:
                    row['ro_ll_index_error'] = f'ray-optics with lenslab\'s indices: {err}'
                else:
                    row['ro_ll_index'] = rms
            rms, changed = rerun_spot(path, lens['surfaces'], stop, nm, stop_r, deg, aimer.chief, apertures=True)
            if rms is not None:
                row['ro_ll_apertures'], row['ro_ll_apertures_changed'] = rms, changed
        result['fields'].append(row)
    # ray-optics' own aiming of the chief ray at the largest field, last: it changes the field spec.
    if an['largest_field_deg'] and an['largest_field_deg'] > 0:
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
    if rel is None or not math.isfinite(rel):
        return '-'
    return f'{rel:+.1e}' + (' **X**' if abs(rel) > tol else '')


def display_name(path):
    return os.path.relpath(path, REPO) if path.startswith(REPO) else os.path.basename(path)


def first_order_table(results):
    lines = ['| prescription | line | EFL | ΔEFL | BFL | ΔBFL | EnP pos | Δ | EnP D | Δ | ExP pos | Δ | ExP D | Δ | '
             'lenslab f/ (real) | ray-optics f/ (real) | Δ | ray-optics f/ (parax.) | Δ (lenslab EFL/EPD) | max Δn |',
             '|' + '---|' * 20]
    for r in results:
        name = display_name(r['file'])
        if 'refused' in r:
            lines.append(f'| {name} | | {r["refused"].replace("|", "/")} |' + ' |' * 17)
            continue
        if 'afocal' in r:
            lines.append(f'| {name} | | afocal in lenslab (no first order, no spots); ray-optics\' paraxial EFL '
                         f'{fmt(r["afocal"]["ro_efl"])} |' + ' |' * 17)
            continue
        for row in r['lines']:
            ll, ro_ = row['ll'], row['ro']
            cells = [name + (' (along the axis ray)' if r.get('decentred') else ''), row['line'], fmt(ll['efl'], 8),
                     flag(scaled_difference(ll, ro_, 'efl'), FIRST_ORDER_TOLERANCE)]
            for k in FIRST_ORDER_KEYS[1:]:
                cells += [fmt(ll[k], 7), flag(scaled_difference(ll, ro_, k), FIRST_ORDER_TOLERANCE)]
            fs = None if None in (ro_.get('fstop'), ll['fstop']) else relative(ll['fstop'], ro_['fstop'])
            fn = None if None in (ro_.get('fno'), ll['fno']) else relative(ll['fno'], ro_['fno'])
            cells += [fmt(ll['fstop'], 6), fmt(ro_.get('fstop'), 6), flag(fs, FIRST_ORDER_TOLERANCE),
                      fmt(ro_.get('fno'), 6), flag(fn, FIRST_ORDER_TOLERANCE), f'{row["dn"]:.1e}']
            lines.append('| ' + ' | '.join(cells) + ' |')
    return '\n'.join(lines)


def spot_table(results):
    lines = ['| prescription | line | field (deg): largest in lenslab (in the file) | lenslab RMS (um) | lenslab sampling '
             '(rings x azimuths, transmission) | ray-optics RMS (um) | ray-optics azimuths (last change, rays), transmission | Δ | Δ with lenslab\'s indices | Δ with lenslab\'s clear radii | '
             'ray-optics chief ray at the stop (mm off centre / stop radius) |',
             '|' + '---|' * 11]
    for r in results:
        if 'refused' in r or 'afocal' in r or 'spots' not in r:
            continue
        name = display_name(r['file'])
        s = r['spots']
        if 'refused' in s:
            lines.append(f'| {name} | {s.get("line", "")} | | {s["refused"]} |' + ' |' * 7)
            continue
        for row in s['fields']:
            field = f'{row["deg"]:.4g}'
            if row['deg'] > 0 and 'file_field' in r:
                field += f' (file: {r["file_field"]:.4g}, {r["file_field_key"]})'
            ll = '-' if row['ll'] is None else f'{row["ll"] * 1e3:.4g}'
            smp = row.get('ll_sampling') or {}
            ll_s = (f'{smp.get("rings")} x {smp.get("azimuths")}, {row["ll_transmission"]:.3g}'
                    if smp and row.get('ll_transmission') is not None else '-')
            if 'error' in row:
                lines.append(f'| {name} | {s["line"]} | {field} | {ll} | {ll_s} | {row["error"]} |' + ' |' * 5)
                continue
            miss = ''
            if row['deg'] > 0 and 'ro_chief_miss' in s:
                miss = f'{s["ro_chief_miss"]:.4g} / {s["stop_r"]:.4g}'
            ro_ = row['ro']
            d = relative(row['ll'], ro_) if row['ll'] is not None and math.isfinite(ro_) and ro_ > 0 else None
            if d is not None and max(row['ll'], ro_) < SPOT_FLOOR_MM:
                d = 0.0   # both under the floor: agreement
            lines.append('| ' + ' | '.join([
                name, s['line'], field, ll, ll_s, fmt(ro_ * 1e3, 4),
                f'{row["ro_azimuths"]} ({row["ro_change"]:.1e}, {row["ro_rays"]}), {row["ro_transmission"]:.3g}',
                flag(d, SPOT_TOLERANCE),
                flag(relative(row['ll'], row['ro_ll_index']), SPOT_TOLERANCE) if 'ro_ll_index' in row
                else row.get('ro_ll_index_error', ''),
                flag(relative(row['ll'], row['ro_ll_apertures']), SPOT_TOLERANCE) if 'ro_ll_apertures' in row else '',
                miss]) + ' |')
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
        print('\n### RMS spot radius about the centroid, paraxial image plane (Δ: lenslab against ray-optics)\n')
        print(spot_table(results))
    print('\n### Notes\n')
    for r in results:
        base = os.path.basename(r['file'])
        for n in r.get('notes', []) + r.get('frame_notes', []) + r.get('glass_notes', []):
            print(f'- {base}: {n}')
        for row in r.get('spots', {}).get('fields', []):
            if row.get('ro_ll_apertures_changed'):
                print(f'- {base} at {row["deg"]:.4g} deg: with lenslab\'s clear radii in ray-optics ('
                      + '; '.join(row['ro_ll_apertures_changed']) + f'): RMS {row["ro_ll_apertures"] * 1e3:.4g} um')
        for row in r.get('lines', []):
            if 'ro_ll_index' in row:
                d = {k: scaled_difference(row['ll'], row['ro_ll_index'], k) for k in FIRST_ORDER_KEYS}
                print(f'- {base} {row["line"]}: with lenslab\'s indices in ray-optics: '
                      + ', '.join(f'{k} {v:+.1e}' for k, v in d.items()))
            if 'ro_paraxial' in row:
                p = row['ro_paraxial']
                print(f'- {base} {row["line"]}: along the axis ray, ray-optics EFL y {fmt(row["ro"]["efl"], 10)}, '
                      f'x {fmt(row["ro"].get("efl_x"), 10)}, BFL {fmt(row["ro"]["bfl"], 10)} from its point on the last '
                      f'surface that bends the light, {fmt(row["ro"].get("bfl_vertex"), 10)} from the foot of the last vertex, '
                      f'entrance pupil diameter y {fmt(row["ro"].get("enp_d"), 10)}, x {fmt(row["ro"].get("enp_d_x"), 10)}; '
                      f'its paraxial (tilts left out) EFL {fmt(p["efl"], 10)}, BFL {fmt(p["bfl"], 10)}')
            if 'error' in row:
                print(f'- {base} {row["line"]}: {row["error"]}')


if __name__ == '__main__':
    main()
