#!/bin/bash
# lenslab's optimiser and tolerancing beside optiland's on issue 37's problem, alternated round by
# round on this machine (CPU seconds of each process; load noted):
#   bench/design/cooke_side_by_side.sh [BUILD=build] [ROUNDS=3] [TRIALS=1000]
# The Cooke triplet (lenses/design/cooke-triplet-50mm.zmx) with each curvature 5% off, alternately
# + and -, optimised on the polychromatic RMS spot at 0/14/20 deg and EFL 50 mm
# (cooke-merit.json); then Monte Carlo tolerancing of the nominal lens (cooke-tolerances.json: radius
# 0.1%, thickness 0.02 mm, decentre 0.01 mm, tilt 0.01 deg, index 5e-4, uniform draws, the back focus
# as compensator), two seeds. optiland runs from bench/peer/optiland (setup.sh first); without it
# only lenslab runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build} rounds=${2:-3} trials=${3:-1000}
lenslab=$build/cli/lenslab
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The perturbed start: CURV of SURF 1..6 times 1.05, 0.95, 1.05, ...
awk '/^SURF /{s=$2} /^  CURV /{ if (s>=1 && s<=6) { $2=sprintf("%.15e", $2*((s%2)?1.05:0.95)); $0="  " $0 } } {print}' \
  lenses/design/cooke-triplet-50mm.zmx > "$work/perturbed.zmx"
optiland=""
if PYTHONPATH=${OPTILAND:-/work/peers/optiland} /usr/bin/python3 -c 'import optiland' 2>/dev/null; then
  optiland=${OPTILAND:-/work/peers/optiland}
fi
field() { /usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {}, {"d": d}))' "$@"; }
echo "load: $(uptime | sed 's/.*load average: //')"
for round in $(seq 1 "$rounds"); do
  "$lenslab" optimise "$work/perturbed.zmx" --merit bench/design/cooke-merit.json --variables curvature:1-6 --json > "$work/opt.json"
  echo "round $round lenslab optimise: CPU $(field "$work/opt.json" 'round(d["cpu_seconds"],3)') s," \
       "$(field "$work/opt.json" 'd["evaluations"]') evaluations, merit $(field "$work/opt.json" '"%.6g -> %.6g" % (d["start"]["merit"], d["end"]["merit"])')," \
       "settled $(field "$work/opt.json" '"%.6g" % d["settled"]["end"]["merit"]'), EFL $(field "$work/opt.json" '"%.6f" % d["end"]["operands"][3]["value"]')"
  if [ -n "$optiland" ]; then
    PYTHONPATH=$optiland /usr/bin/python3 bench/peer/optiland/cooke_optimise.py --repeats 1 --json "$work/optiland.json" > /dev/null
    echo "round $round optiland optimise: $(field "$work/optiland.json" '"CPU %.3f s, %d evaluations, merit %.6g -> %.6g" % (d["runs"][0]["cpu_s"], d["runs"][0]["merit_evaluations"], d["runs"][0]["merit_before"], d["runs"][0]["merit_after"])')"
  fi
done
nominal=$("$lenslab" optimise lenses/design/cooke-triplet-50mm.zmx --merit bench/design/cooke-merit.json --variables curvature:1-6 --max-iterations 1 --json | /usr/bin/python3 -c 'import json,sys; d=json.load(sys.stdin); print("%.6g (settled %.6g)" % (d["start"]["merit"], d["settled"]["start"]["merit"]))')
echo "lenslab nominal design's merit: $nominal"
for seed in 1 2; do
  "$lenslab" tolerance lenses/design/cooke-triplet-50mm.zmx --merit bench/design/cooke-merit.json --spec bench/design/cooke-tolerances.json \
    --trials "$trials" --seed "$seed" --json > "$work/tol$seed.json"
  echo "lenslab tolerance seed $seed: $(field "$work/tol$seed.json" '"%d trials, CPU %.2f s (%.4f s a trial); merit p50 %.4g p90 %.4g p98 %.4g; spot 14 deg p90 %.5g mm; EFL p90 %.5f" % (d["monte_carlo"]["trials"], d["cpu_seconds"]["monte_carlo"], d["cpu_seconds"]["monte_carlo"]/d["monte_carlo"]["trials"], d["monte_carlo"]["merit"]["p50"], d["monte_carlo"]["merit"]["p90"], d["monte_carlo"]["merit"]["p98"], d["monte_carlo"]["operands"][1]["distribution"]["p90"], d["monte_carlo"]["operands"][3]["distribution"]["p90"])')"
done
/usr/bin/python3 - "$work/tol1.json" "$work/tol2.json" <<'PY'
import json, sys
a, b = (json.load(open(p))["monte_carlo"] for p in sys.argv[1:3])
rows = [("merit", a["merit"], b["merit"])] + [(x["description"], x["distribution"], y["distribution"]) for x, y in zip(a["operands"], b["operands"])]
print("percentiles, seed 1 / seed 2 (relative difference):")
for name, x, y in rows:
    print("  %-32s" % name + "  ".join("%s %.5g / %.5g (%.2f%%)" % (p, x[p], y[p], 100 * abs(x[p] - y[p]) / max(abs(x[p]), abs(y[p]))) for p in ("p50", "p90", "p98")))
PY
if [ -n "$optiland" ]; then
  PYTHONPATH=$optiland /usr/bin/python3 bench/peer/optiland/cooke_tolerance.py --trials 30 --index --json "$work/optiland-tol.json" > /dev/null
  echo "optiland tolerance: $(field "$work/optiland-tol.json" '"%d trials, CPU %.2f s (%.3f s a trial)" % (d["trials"], d["cpu_s"], d["cpu_s"]/d["trials"])')"
fi
echo "load: $(uptime | sed 's/.*load average: //')"
