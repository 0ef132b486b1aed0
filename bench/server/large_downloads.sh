#!/bin/bash
# Resident memory of `lenslab serve` while CLIENTS clients download a 1920x1920 render over and
# over, half its image.exr and half its /pixels (issue 23: each used to be read or decoded whole).
# usage: bench/server/large_downloads.sh LENSLAB_BINARY [SECONDS (60)] [CLIENTS (16)]   (prints Markdown)
set -euo pipefail
binary=$1 seconds=${2:-60} clients=${3:-16}
folder=$(mktemp -d)
"$binary" serve --port 0 --data "$folder/data" --access-log /dev/null >"$folder/server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$folder"' EXIT
until port=$(grep -o 'listening on http://[^ ]*:[0-9]*/' "$folder/server.log" | grep -o '[0-9]*/$' | tr -d /); do sleep 0.2; done
url=http://127.0.0.1:$port
id=$(curl -s -X POST -H 'Content-Type: application/json' -d '{"spp":1,"width":1920,"height":1920,"mode":"thick"}' \
  "$url/api/renders" | grep -o 'render-[0-9a-f]*' | head -1)
until curl -s "$url/api/renders/$id" | grep -q '"state":"done"'; do sleep 1; done
resident() { awk '/VmRSS/ {print int($2 / 1024)}' "/proc/$server/status"; }
echo "| t s | RSS MiB | downloads |"
echo "|---|---|---|"
echo "| 0 | $(resident) | 0 |"
end=$((SECONDS + seconds))
downloaders=()
for c in $(seq "$clients"); do
  resource=$([ $((c % 2)) = 0 ] && echo image.exr || echo pixels)
  (while [ $SECONDS -lt $end ]; do curl -s -o /dev/null "$url/api/renders/$id/$resource"; echo >>"$folder/count"; done) &
  downloaders+=($!)
done
for t in $(seq 10 10 "$seconds"); do
  sleep 10
  echo "| $t | $(resident) | $(wc -l <"$folder/count" 2>/dev/null || echo 0) |"
done
wait "${downloaders[@]}"
