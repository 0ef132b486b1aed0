#!/usr/bin/env bash
# Renders lenslab's own environment map, scenes/maps/sky.exr (256 x 128, latitude-longitude, y up),
# with lenslab's environment camera: a sky of five emitting bands paler toward the horizon, a
# plain ground lit by them and by the materials scene's sun, and a few coloured towers and
# cones on the horizon for reflections to show. Needs build/cli/lenslab (scripts/build.sh).
# The scene is written here rather than under scenes/, which holds the scenes the report renders.
set -euo pipefail
cd "$(dirname "$0")/.."
scene="$(mktemp --suffix=.pbrt)"
trap 'rm -f "$scene"' EXIT

# A band of the sky dome (radius 500) between two elevations, in degrees, with its radiance.
band() {
  awk -v lo="$1" -v hi="$2" -v rgb="$3" 'BEGIN {
    pi = atan2(0, -1); r = 500
    printf "AttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [%s] \"bool twosided\" true\n", rgb
    printf "  Rotate -90 1 0 0\n  Shape \"sphere\" \"float radius\" %d \"float zmin\" %.3f \"float zmax\" %.3f\nAttributeEnd\n",
           r, r * sin(lo * pi / 180), r * sin(hi * pi / 180) }'
}

# An upright cylinder (a tower) or cone (a tree) standing on the ground at (x, z).
upright() {  # shape x z "params" "rgb Kd"
  printf 'AttributeBegin\n  Material "matte" "rgb Kd" [%s]\n  Translate %s 0 %s\n  Rotate -90 1 0 0\n  Shape "%s" %s\nAttributeEnd\n' \
    "$5" "$2" "$3" "$1" "$4"
}

{
  # The camera 1.5 m above the ground, unrotated: the map's directions are the world's.
  echo 'Translate 0 -1.5 0'
  echo 'Camera "environment"'
  echo 'Film "image" "integer xresolution" 256 "integer yresolution" 128 "string filename" "sky.exr"'
  echo 'Sampler "sobol" "integer pixelsamples" 256'
  echo 'Integrator "path" "integer maxdepth" 3'
  echo 'WorldBegin'
  echo 'LightSource "distant" "point from" [-2 4 -3] "point to" [0 0 0] "rgb L" [2.2 2.1 1.9]'
  band 0 4 "1.05 1.05 1.0"
  band 4 12 "0.8 0.88 1.0"
  band 12 30 "0.55 0.68 0.95"
  band 30 55 "0.38 0.52 0.88"
  band 55 90 "0.26 0.38 0.78"
  echo 'AttributeBegin'
  echo '  Material "matte" "rgb Kd" [0.3 0.32 0.24]'
  echo '  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point P" [-600 0 -600  600 0 -600  600 0 600  -600 0 600]'
  echo 'AttributeEnd'
  upright cylinder 40 25 '"float radius" 5 "float zmin" 0 "float zmax" 18' "0.7 0.15 0.1"
  upright cylinder -35 40 '"float radius" 8 "float zmin" 0 "float zmax" 10' "0.8 0.75 0.6"
  upright cylinder 10 -50 '"float radius" 4 "float zmin" 0 "float zmax" 25' "0.15 0.25 0.7"
  upright cone -45 -20 '"float radius" 6 "float height" 14' "0.1 0.4 0.1"
  upright cone -38 -30 '"float radius" 5 "float height" 11' "0.12 0.45 0.12"
  upright cone 50 -15 '"float radius" 7 "float height" 15' "0.1 0.35 0.08"
  echo 'WorldEnd'
} > "$scene"

mkdir -p scenes/maps
build/cli/lenslab render "$scene" -o scenes/maps/sky.exr -o "${SKY_PNG:-/tmp/sky.png}" --quiet
