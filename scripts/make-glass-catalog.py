#!/usr/bin/python3
"""Converts the catalog glasses of the refractiveindex.info database into optics/data/glass-catalog.tsv.

    scripts/make-glass-catalog.py --git-dir PATH/refractiveindex.info-database/.git [--output FILE]

Reads the database straight from git (a bare repository or a checkout's .git) at HEAD, so the
commit hash recorded in the output names exactly what was converted. Needs python3-yaml.

Only the six makers' optical catalogs are taken (database/data/specs/<maker>/...), every folder
except Schott's infrared glasses (chalcogenides measured from 0.6-1 um, opaque in the visible).
A glass needs a dispersion formula and the maker's published nd and Vd; the others are skipped
and counted. A seventh catalog, MISC, holds the few materials lens files name under Zemax's MISC
catalog (fused silica, the fluoride crystals, sapphire), from the measurements the database cites;
their nd and Vd are computed from the formula, as no maker publishes them. The coefficients are rewritten into the two layouts optics/prescription/Medium.h documents, so
the C++ side reads numbers and never exponents:

  Sellmeier         A B1 C1 B2 C2 ...       n^2 = 1 + A + sum Bi L^2 / (L^2 - Ci)   (L in um, Ci in um^2)
  SchottPolynomial  a0 a1 a2 a3 ... a8      n^2 = a0 + a1 L^2 + a2 L^4 + a3 L^-2 + ... + a8 L^-12

Database formula 2 is the Sellmeier layout as it stands; formula 1 (the same with Ci written as
square roots) has its Ci squared; formula 3 (n^2 = c0 + sum c_k L^e_k) is placed by exponent.
"""

import argparse
import math
import re
import subprocess
import sys

import yaml

REPOSITORY = "https://github.com/polyanskiy/refractiveindex.info-database"
MAKERS = ["schott", "ohara", "hoya", "cdgm", "hikari", "sumita"]  # the order lookups use by default
# MISC: (name as Zemax's MISC catalog writes it, the database's measurement of it).
MISC = [("SILICA", "database/data/main/SiO2/nk/Malitson.yml"),      # Malitson 1965, fused silica
        ("CAF2", "database/data/main/CaF2/nk/Malitson.yml"),        # Malitson 1963
        ("BAF2", "database/data/main/BaF2/nk/Malitson.yml"),        # Malitson 1964
        ("SAPPHIRE", "database/data/main/Al2O3/nk/Malitson-o.yml"),  # ordinary ray, Malitson & Dodge 1972
        ("MGF2", "database/data/main/MgF2/nk/Dodge-o.yml")]         # ordinary ray, Dodge 1984
SKIPPED_FOLDERS = {("schott", "infrared")}
POLYNOMIAL_SLOTS = {0: 0, 2: 1, 4: 2, -2: 3, -4: 4, -6: 5, -8: 6, -10: 7, -12: 8}
MAX_COEFFICIENTS = 12  # std::array<double, 12> in optics/prescription/Medium.h


def git(git_dir, *args):
    return subprocess.run(["git", "--git-dir=" + git_dir, *args], check=True,
                          capture_output=True, text=True).stdout


def number_text(value):
    return "0" if value == 0 else f"{value:.15g}"


def convert_formula(kind, tokens):
    """(formula name, coefficient texts) in optics/prescription/Medium.h's layout, or None for other formulas."""
    values = [float(t) for t in tokens]
    if kind in ("formula 1", "formula 2"):
        if kind == "formula 1":
            tokens = tokens[:1] + [number_text(v * v) if i % 2 == 0 else tokens[i]
                                   for i, v in enumerate(values[1:], start=1)]
        return "Sellmeier", tokens
    if kind == "formula 3":
        slots = ["0"] * len(POLYNOMIAL_SLOTS)
        slots[0] = tokens[0]
        for coefficient, exponent in zip(tokens[1::2], values[2::2]):
            if exponent not in POLYNOMIAL_SLOTS:
                raise ValueError(f"exponent {exponent} has no slot")
            slots[POLYNOMIAL_SLOTS[exponent]] = coefficient
        return "SchottPolynomial", slots
    return None


def refractive_index(formula, coefficients, nm):
    """The same evaluation as optics/prescription/Medium.cpp, to check the data before it is written."""
    c = [float(t) for t in coefficients] + [0.0] * MAX_COEFFICIENTS
    x = (nm / 1000.0) ** 2
    if formula == "Sellmeier":
        n2 = 1 + c[0] + sum(c[i] * x / (x - c[i + 1]) for i in range(1, len(coefficients), 2))
    else:
        n2 = c[0] + c[1] * x + c[2] * x * x + sum(c[2 + k] * x ** -k for k in range(1, 7))
    return math.sqrt(n2) if n2 > 0 else float("nan")


def trimmed(tokens):
    tokens = ["0" if float(t) == 0 else t for t in tokens]
    while len(tokens) > 1 and tokens[-1] == "0":
        tokens.pop()
    return tokens


def glass_row(maker, name, document, computed_nd_vd=False):
    properties = document.get("PROPERTIES") or {}
    formulas = [d for d in document.get("DATA", []) if d["type"].startswith("formula")]
    if len(formulas) != 1 or (not computed_nd_vd and ("nd" not in properties or "Vd" not in properties)):
        return None
    data = formulas[0]
    converted = convert_formula(data["type"], str(data["coefficients"]).split())
    if converted is None:
        return None
    formula, coefficients = converted
    coefficients = trimmed(coefficients)
    if len(coefficients) > MAX_COEFFICIENTS:
        raise ValueError(f"{maker} {name}: {len(coefficients)} coefficients")
    low, high = (float(v) * 1000 for v in str(data["wavelength_range"]).split())
    if computed_nd_vd:
        nd, nf, nc = (refractive_index(formula, coefficients, nm) for nm in (587.5618, 486.1327, 656.2725))
        properties = {"nd": round(nd, 6), "Vd": round((nd - 1) / (nf - nc), 4)}
    return {"maker": maker.upper(), "name": name, "formula": formula, "coefficients": coefficients,
            "min": low, "max": high, "nd": float(properties["nd"]), "vd": float(properties["Vd"])}


def check(row):
    """Problems that would reach a render: NaN or n < 1 over 360-830 nm."""
    bad = [nm for nm in range(360, 831) if not refractive_index(row["formula"], row["coefficients"], nm) >= 1]
    return f"{row['maker']} {row['name']}: n undefined at {bad[0]} nm" if bad else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--git-dir", required=True, help="the database's git directory")
    parser.add_argument("--output", default="optics/data/glass-catalog.tsv")
    args = parser.parse_args()

    commit, date = git(args.git_dir, "log", "-1", "--format=%H %cs", "HEAD").split()
    paths = git(args.git_dir, "ls-tree", "-r", "--name-only", "HEAD", "database/data/specs").split("\n")
    rows, skipped = [], 0
    for maker in MAKERS:
        for path in sorted(p for p in paths if p.startswith(f"database/data/specs/{maker}/")):
            parts = path.split("/")
            if not path.endswith(".yml") or len(parts) != 6 or (maker, parts[4]) in SKIPPED_FOLDERS:
                continue
            row = glass_row(maker, parts[5][:-4], yaml.safe_load(git(args.git_dir, "show", "HEAD:" + path)))
            if row is None:
                skipped += 1
                continue
            problem = check(row)
            if problem:
                raise SystemExit(problem)
            rows.append(row)
    for name, path in MISC:
        row = glass_row("misc", name, yaml.safe_load(git(args.git_dir, "show", "HEAD:" + path)), computed_nd_vd=True)
        problem = check(row)
        if problem:
            raise SystemExit(problem)
        rows.append(row)

    keys = [(r["maker"], re.sub(r"[\s_-]", "", r["name"]).upper()) for r in rows]
    if len(set(keys)) != len(keys):  # optics/prescription/GlassCatalog.cpp matches names without these
        raise SystemExit(f"names of one maker differ only in case, spaces, _ or -: {sorted(keys)}")

    with open(args.output, "w", encoding="utf-8", newline="\n") as out:
        out.write(f"# Catalog glasses converted from the refractiveindex.info database, {REPOSITORY}\n"
                  f"# commit {commit} ({date}); public domain, CC0 1.0 (waived by the database's authors).\n"
                  "# Written by scripts/make-glass-catalog.py; do not edit by hand.\n"
                  "# maker<TAB>name<TAB>formula<TAB>min nm<TAB>max nm<TAB>nd<TAB>Vd<TAB>coefficients"
                  " (optics/prescription/Medium.h layout, wavelength in um)\n")
        for r in rows:
            out.write("\t".join([r["maker"], r["name"], r["formula"], f"{r['min']:g}", f"{r['max']:g}",
                                 number_text(r["nd"]), number_text(r["vd"]), " ".join(r["coefficients"])]) + "\n")

    def deviation(r, key):
        n = [refractive_index(r["formula"], r["coefficients"], nm) for nm in (587.5618, 486.1327, 656.2725)]
        return abs(n[0] - r["nd"]) if key == "nd" else abs((n[0] - 1) / (n[1] - n[2]) - r["vd"])
    worst = {k: max(rows, key=lambda r: deviation(r, k)) for k in ("nd", "vd")}
    counts = {m.upper(): sum(r["maker"] == m.upper() for r in rows) for m in MAKERS + ["misc"]}
    print(f"{len(rows)} glasses from commit {commit[:12]} ({date}), {skipped} skipped without a formula"
          f" or published nd/Vd: {counts}", file=sys.stderr)
    for key, r in worst.items():
        print(f"largest |computed - published| {key}: {deviation(r, key):.2e} ({r['maker']} {r['name']})",
              file=sys.stderr)


if __name__ == "__main__":
    main()
