#!/usr/bin/env bash
# Renders scenes with pbrt-v3 and with lenslab, one after the other on the same machine and thread
# count, and prints a Markdown table: times, the ratio lenslab / pbrt-v3 of each channel's mean,
# and the relative RMSE (RMS of the difference over pbrt-v3's mean) of the pixels and of 10 x 10
# pixel block means (mostly noise in the first, mostly bias in the second). pbrt-v3 is a peer
# program built outside this repository; this script only runs it. Not part of the CTest suite.
#
#   bench/peer/compare.sh PBRT_V3_BINARY [options] SCENE.pbrt...
#     --lenslab PATH   lenslab binary (default build/cli/lenslab)
#     --width N        image width; the height keeps the scene's aspect (default 200)
#     --spp N          samples per pixel for both (default 64)
#     --threads N      threads for both (default 1)
#     --out DIR        where the EXRs, PNGs and difference images go (default /tmp/lenslab-peer)
#
# Scenes must use pbrt-v3's conventions (see bench/README.md, "Side by side with pbrt-v3"), with
# Film and Sampler in the named file itself (they are rewritten for the requested size and spp in
# a temporary copy beside it, so that relative paths still resolve). Needs oiiotool and idiff
# (Debian: openimageio-tools). The image files the bench scenes name (grid.png, sky.exr) are made
# here when missing.
set -euo pipefail

usage() { sed -n '8,13p' "$0" >&2; exit 2; }
[[ $# -ge 2 ]] || usage
pbrt=$1; shift
here=$(cd "$(dirname "$0")" && pwd)
lenslab=$here/../../build/cli/lenslab
width=200 spp=64 threads=1 out=/tmp/lenslab-peer
scenes=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --lenslab) lenslab=$2; shift 2 ;;
        --width) width=$2; shift 2 ;;
        --spp) spp=$2; shift 2 ;;
        --threads) threads=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -*) usage ;;
        *) scenes+=("$1"); shift ;;
    esac
done
for tool in "$pbrt" "$lenslab" oiiotool idiff; do
    command -v "$tool" >/dev/null || { echo "compare.sh: $tool not found" >&2; exit 1; }
done
mkdir -p "$out"

# The bench scenes' images: an 8-bit sRGB grid and a lat-long sky that is brighter and warmer at
# the upper left than at the upper right, so a mirrored or rotated map shows.
[[ -f $here/scenes/grid.png ]] || oiiotool \
    --pattern checker:width=8:height=8:color1=0.9,0.6,0.1:color2=0.1,0.2,0.7 64x64 3 \
    -d uint8 -o "$here/scenes/grid.png"
[[ -f $here/scenes/sky.exr ]] || oiiotool \
    --pattern fill:topleft=3,2,1:topright=0.3,0.6,2:bottomleft=0.2,0.15,0.1:bottomright=0.05,0.08,0.05 128x64 3 \
    -d half -o "$here/scenes/sky.exr"

# The first integer given for parameter $2 in scene file $1 (the Film's resolutions).
intParam() { grep -o "\"integer $2\" *\[\? *[0-9]\+" "$1" | grep -o '[0-9]\+$' | head -1 || true; }

# Runs a command with its output in log file $1; prints its CPU seconds (user + system) and wall
# seconds. A failed render shows as a missing image, reported below.
timed() {
    local log=$1 TIMEFORMAT='%R %U %S'
    shift
    { time "$@" >"$log" 2>&1 || true; } 2>&1 | awk '{ printf "%.2f %.2f\n", $2 + $3, $1 }'
}

# Channel means of an EXR's first three channels.
means() { oiiotool "$1" --ch 0,1,2 --printstats | awk '/Stats Avg:/ { print $3, $4, $5 }'; }

# RMS difference of two EXRs over their mean (the mean of $3's three channel means).
relativeRmse() {
    local rms
    rms=$(idiff -a "$1" "$2" 2>&1 | awk -F'[ =]+' '/RMS error/ { print $NF }' || true)
    awk -v e="$rms" -v m="$3" 'BEGIN { split(m, y, " "); mean = (y[1] + y[2] + y[3]) / 3;
        printf "%.3f", (mean > 0 ? e / mean : 0) }'
}

copy=
trap 'rm -f "$copy"' EXIT
echo "| scene | pbrt-v3 CPU s (wall) | lenslab CPU s (wall) | mean ratio R G B | relative RMSE | of 10x10 blocks |"
echo "|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .pbrt)
    xres=$(intParam "$scene" xresolution); yres=$(intParam "$scene" yresolution)
    xres=${xres:-640} yres=${yres:-480}  # pbrt-v3's defaults
    height=$(( (yres * width + xres / 2) / xres ))
    copy=$(dirname "$scene")/.peer-$$-$name.pbrt
    sed -e "s/\"integer xresolution\" *\[\? *[0-9]\+ *\]\?/\"integer xresolution\" $width/" \
        -e "s/\"integer yresolution\" *\[\? *[0-9]\+ *\]\?/\"integer yresolution\" $height/" \
        -e "s/\"integer pixelsamples\" *\[\? *[0-9]\+ *\]\?/\"integer pixelsamples\" $spp/" \
        "$scene" >"$copy"
    ref=$out/$name.pbrt-v3.exr mine=$out/$name.lenslab.exr
    rm -f "$ref" "$mine"
    pbrtTime=$(timed "$out/$name.pbrt-v3.log" "$pbrt" --nthreads "$threads" --outfile "$ref" "$copy")
    mineTime=$(timed "$out/$name.lenslab.log" "$lenslab" render "$copy" -o "$mine" \
        --threads "$threads" --spp "$spp" --quiet)
    rm -f "$copy"
    for f in "$ref" "$mine"; do
        [[ -f $f ]] || { echo "| $name | failed: see ${f%.exr}.log |"; continue 2; }
    done
    read -r r0 g0 b0 <<<"$(means "$ref")"
    read -r r1 g1 b1 <<<"$(means "$mine")"
    ratios=$(awk -v a="$r1 $g1 $b1" -v b="$r0 $g0 $b0" 'BEGIN { split(a, x, " "); split(b, y, " ");
        for (i = 1; i <= 3; i++) printf "%s%.3f", (i > 1 ? " " : ""), (y[i] > 0 ? x[i] / y[i] : 0) }')
    rel=$(relativeRmse "$mine" "$ref" "$r0 $g0 $b0")
    # Averaging 10 x 10 pixel blocks divides the noise by about 10 and keeps any bias.
    for f in "$ref" "$mine"; do
        oiiotool "$f" --ch 0,1,2 --resize:filter=box "$((width / 10))x$((height / 10))" -o "${f%.exr}.blocks.exr"
    done
    relBlocks=$(relativeRmse "${mine%.exr}.blocks.exr" "${ref%.exr}.blocks.exr" "$r0 $g0 $b0")
    for f in "$ref" "$mine"; do oiiotool "$f" --ch 0,1,2 --tocolorspace sRGB -d uint8 -o "${f%.exr}.png"; done
    oiiotool "$mine" --ch 0,1,2 "$ref" --ch 0,1,2 --absdiff --mulc 4 --tocolorspace sRGB -d uint8 \
        -o "$out/$name.diff.png"
    read -r pc pw <<<"$pbrtTime"; read -r lc lw <<<"$mineTime"
    echo "| $name | $pc ($pw) | $lc ($lw) | $ratios | $rel | $relBlocks |"
done
