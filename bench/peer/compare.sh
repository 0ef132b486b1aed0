#!/usr/bin/env bash
# Renders scenes with a peer pbrt (pbrt-v3 or pbrt-v4) and with lenslab, one after the other on the
# same machine and thread count, and prints a Markdown table: CPU times and their ratio, the ratio
# lenslab / peer of each channel's mean, the relative RMSE (RMS of the difference over the peer's
# mean) of the pixels and of 10 x 10 pixel block means (mostly noise in the first, mostly bias in
# the second), the block RMSE that noise alone would give, and the Pearson correlation of the block
# means. The RMSEs and the correlation are taken with both images clamped at the peer's 99th
# percentile pixel value, so that a visible light or a few fireflies do not decide them. The peer
# is built outside this repository; this script only runs it. Not part of CTest.
#
#   bench/peer/compare.sh PBRT_BINARY [options] SCENE.pbrt...
#     --peer v3|v4     which pbrt the binary is (default v3)
#     --lenslab PATH   lenslab binary (default build/cli/lenslab)
#     --width N        image width; the height keeps the scene's aspect (default 200)
#     --spp N          samples per pixel for both (default 64)
#     --threads N      threads for both (default 1)
#     --out DIR        where the EXRs, PNGs and difference images go (default /tmp/lenslab-peer)
#
# Scenes must use the peer's conventions (see bench/README.md, "Side by side with pbrt-v3" and
# "pbrt-v4 scenes"), with Film and Sampler in the named file itself (they are rewritten for the
# requested size and spp in a temporary copy beside it, so that relative paths still resolve). Needs
# oiiotool and idiff (Debian: openimageio-tools). The image files the bench scenes name (grid.png,
# sky.exr) are made here when missing.
set -euo pipefail

usage() { sed -n '9,15p' "$0" >&2; exit 2; }
[[ $# -ge 2 ]] || usage
pbrt=$1; shift
here=$(cd "$(dirname "$0")" && pwd)
lenslab=$here/../../build/cli/lenslab
peer=v3 width=200 spp=64 threads=1 out=/tmp/lenslab-peer
scenes=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --peer) peer=$2; shift 2 ;;
        --lenslab) lenslab=$2; shift 2 ;;
        --width) width=$2; shift 2 ;;
        --spp) spp=$2; shift 2 ;;
        --threads) threads=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -*) usage ;;
        *) scenes+=("$1"); shift ;;
    esac
done
[[ $peer == v3 || $peer == v4 ]] || usage
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

# The first integer given for parameter $2 in scene file $1 (the Film's resolutions), comments
# skipped.
intParam() {
    sed 's/#.*//' "$1" | grep -o "\"integer $2\" *\[\? *[0-9]\+" | grep -o '[0-9]\+$' | head -1 || true
}

# Runs a command with its output in log file $1; prints its CPU seconds (user + system) and wall
# seconds. A failed render shows as a missing image, reported below.
timed() {
    local log=$1 TIMEFORMAT='%R %U %S'
    shift
    { time "$@" >"$log" 2>&1 || true; } 2>&1 | awk '{ printf "%.2f %.2f\n", $2 + $3, $1 }'
}

# Renders scene copy $1 with the peer into EXR $2, logging to $3; prints CPU and wall seconds.
# pbrt-v4 is given the spp on its command line as well (its --spp overrides any sampler).
renderPeer() {
    case $peer in
        v3) timed "$3" "$pbrt" --nthreads "$threads" --outfile "$2" "$1" ;;
        v4) timed "$3" "$pbrt" --nthreads "$threads" --spp "$spp" --outfile "$2" "$1" ;;
    esac
}

# The 99th percentile of an EXR's first three channels' values, pooled.
percentile99() {
    oiiotool --dumpdata "$1" | awk -F': ' '/Pixel \(/ { split($2, v, " "); print v[1]; print v[2]; print v[3] }' |
        sort -g | awk '{ v[NR] = $1 } END { i = int(0.99 * NR); if (i < 1) i = 1; print v[i] }'
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

# Pearson correlation of two same-sized EXRs' values, all channels pooled.
correlation() {
    paste <(oiiotool --dumpdata "$1" | grep 'Pixel (') <(oiiotool --dumpdata "$2" | grep 'Pixel (') |
        awk -F'[):\t]+' '{ split($2, a, " "); split($4, b, " ");
            for (i = 1; i <= 3; i++) { x = a[i]; y = b[i]; n++; sx += x; sy += y;
                sxx += x * x; syy += y * y; sxy += x * y } }
            END { vx = sxx - sx * sx / n; vy = syy - sy * sy / n;
                printf "%.3f", (vx > 0 && vy > 0 ? (sxy - sx * sy / n) / sqrt(vx * vy) : 0) }'
}

copy=
trap 'rm -f "$copy"' EXIT
echo "| scene | pbrt-$peer CPU s (wall) | lenslab CPU s (wall) | CPU ratio | mean ratio R G B | relative RMSE | of 10x10 blocks | noise alone | block correlation |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .pbrt)
    xres=$(intParam "$scene" xresolution); yres=$(intParam "$scene" yresolution)
    case $peer in  # the defaults
        v3) xres=${xres:-640} yres=${yres:-480} ;;
        v4) xres=${xres:-1280} yres=${yres:-720} ;;
    esac
    height=$(( (yres * width + xres / 2) / xres ))
    copy=$(dirname "$scene")/.peer-$$-$name.pbrt
    # pmj02bn: this project's pbrt-v4 build lacks its tables (bench/README.md); halton stands in.
    sed -e "s/\"integer xresolution\" *\[\? *[0-9]\+ *\]\?/\"integer xresolution\" $width/" \
        -e "s/\"integer yresolution\" *\[\? *[0-9]\+ *\]\?/\"integer yresolution\" $height/" \
        -e "s/\"integer pixelsamples\" *\[\? *[0-9]\+ *\]\?/\"integer pixelsamples\" $spp/" \
        -e 's/Sampler *"pmj02bn"/Sampler "halton"/' \
        "$scene" >"$copy"
    ref=$out/$name.pbrt-$peer.exr mine=$out/$name.lenslab.exr
    rm -f "$ref" "$mine"
    pbrtTime=$(renderPeer "$copy" "$ref" "$out/$name.pbrt-$peer.log")
    mineTime=$(timed "$out/$name.lenslab.log" "$lenslab" render "$copy" -o "$mine" \
        --threads "$threads" --spp "$spp" --quiet)
    rm -f "$copy"
    for f in "$ref" "$mine"; do
        [[ -f $f ]] || { echo "| $name | failed: see ${f%.exr}.log |"; continue 2; }
        # A crop window: pbrt-v4 keeps the full frame as the display window around the crop's
        # pixels, lenslab writes the crop alone. Both become the crop's pixels at the origin, so
        # the block means below average the same pixels.
        oiiotool "$f" --origin +0+0 --fullpixels -o "$f"
    done
    read -r r0 g0 b0 <<<"$(means "$ref")"
    read -r r1 g1 b1 <<<"$(means "$mine")"
    ratios=$(awk -v a="$r1 $g1 $b1" -v b="$r0 $g0 $b0" 'BEGIN { split(a, x, " "); split(b, y, " ");
        for (i = 1; i <= 3; i++) printf "%s%.3f", (i > 1 ? " " : ""), (y[i] > 0 ? x[i] / y[i] : 0) }')
    ceiling=$(percentile99 "$ref")
    for f in "$ref" "$mine"; do
        oiiotool "$f" --ch 0,1,2 --clamp:min=0:max="$ceiling" -o "${f%.exr}.clamped.exr"
    done
    refClamped=${ref%.exr}.clamped.exr mineClamped=${mine%.exr}.clamped.exr
    clampedMeans=$(means "$refClamped")
    rel=$(relativeRmse "$mineClamped" "$refClamped" "$clampedMeans")
    # Averaging 10 x 10 pixel blocks divides independent pixel noise by 10 and keeps any bias, so
    # a tenth of the pixels' RMSE is what the blocks would show from noise alone (an upper bound:
    # it counts the bias too).
    for f in "$refClamped" "$mineClamped"; do
        oiiotool "$f" --resize:filter=box "$((width / 10))x$((height / 10))" -o "${f%.exr}.blocks.exr"
    done
    relBlocks=$(relativeRmse "${mineClamped%.exr}.blocks.exr" "${refClamped%.exr}.blocks.exr" "$clampedMeans")
    floor=$(awk -v r="$rel" 'BEGIN { printf "%.3f", r / 10 }')
    corr=$(correlation "${mineClamped%.exr}.blocks.exr" "${refClamped%.exr}.blocks.exr")
    for f in "$ref" "$mine"; do oiiotool "$f" --ch 0,1,2 --tocolorspace sRGB -d uint8 -o "${f%.exr}.png"; done
    oiiotool "$mine" --ch 0,1,2 "$ref" --ch 0,1,2 --absdiff --mulc 4 --tocolorspace sRGB -d uint8 \
        -o "$out/$name.diff.png"
    read -r pc pw <<<"$pbrtTime"; read -r lc lw <<<"$mineTime"
    cpuRatio=$(awk -v a="$lc" -v b="$pc" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }')
    echo "| $name | $pc ($pw) | $lc ($lw) | $cpuRatio | $ratios | $rel | $relBlocks | $floor | $corr |"
done
