#!/usr/bin/python3
"""What optiland's issue #630 does to the issue-37 merit, before and after the fix.

    PYTHONPATH=/work/peers/optiland /usr/bin/python3 bench/peer/optiland/issue630_demo.py

Needs the PATCHED snapshot (setup.sh). For the "unfixed" half it puts back the
snapshot's original BaseMaterial._array_metadata_key (numpy branch, copied
below): the n()/k() cache key of a wavelength array with more than 64 elements
(here the 91 rays of 5 hexapolar rings) was its buffer ADDRESS plus shape,
strides and dtype. rms_spot_size(wavelength='all') traces 0.48, 0.55, 0.65 um
in turn, each with a fresh 91-element wavelength array; when the allocator
hands a new one the freed address of an earlier one, n() returns the earlier
wavelength's index. The merit of one unchanged lens then varies from call to
call. The fixed key (content digest) gives one value.
"""

import sys

import numpy as np

sys.dont_write_bytecode = True   # no __pycache__ inside the repository

import cooke_common as cc
from optiland.materials.base import BaseMaterial

EVALUATIONS = 50
FIXED_KEY = BaseMaterial.__dict__["_array_metadata_key"]


def unfixed_key(value):
    """The snapshot's original key for numpy arrays (address-based)."""
    return ("ndarray-meta", int(value.__array_interface__["data"][0]),
            tuple(value.shape), tuple(value.strides), str(value.dtype))


def measure(label):
    lens = cc.nominal_lens()
    problem = cc.make_problem(lens, with_variables=False)
    merits = np.array([cc.merit(problem) for _ in range(EVALUATIONS)])
    spots = np.array([[cc.rms_spot(lens, f, "all") for f in cc.FIELDS_DEG]
                      for _ in range(EVALUATIONS)])
    print(f"{label}: nominal merit over {EVALUATIONS} evaluations of the same lens: "
          f"{len(np.unique(merits))} distinct values, min {merits.min():.9g}, "
          f"max {merits.max():.9g}")
    for i, f in enumerate(cc.FIELDS_DEG):
        s = spots[:, i]
        print(f"    RMS {f:g} deg: {len(np.unique(s))} distinct, min {s.min():.9f} "
              f"max {s.max():.9f} mm")


BaseMaterial._array_metadata_key = staticmethod(unfixed_key)
measure("unfixed (address key)")
BaseMaterial._array_metadata_key = FIXED_KEY
measure("fixed (content key)  ")
