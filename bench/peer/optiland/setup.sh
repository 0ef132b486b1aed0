#!/bin/bash
# Set up optiland as a peer for lenslab issue 37, OUTSIDE this repository.
#
#   bench/peer/optiland/setup.sh [GIT_DIR] [DEST]
#
#   GIT_DIR  optiland's (bare) git directory, default /work/.mirror/optiland+optiland/repo
#   DEST     where to export its HEAD, default /work/peers/optiland (must be outside
#            the repository; an existing DEST is left as it is, only patched if needed)
#
# 1. exports HEAD (blobs absent from the snapshot are skipped: on the snapshot used,
#    commit 0b9e54b9, only optiland_gui/resources/resources_rc.py, which is not imported;
#    git still prints an "invalid object" line for it, harmlessly);
# 2. applies issue630-cache-key.patch (optiland issue #630, fixed upstream by PR #632:
#    the refractive-index cache key of large wavelength arrays was their buffer address,
#    so a new array at a freed address got the old array's indices);
# 3. installs Debian 12's Python packages (needs root; SKIP_APT=1 skips it).
#
# Then: PYTHONPATH=$DEST /usr/bin/python3 bench/peer/optiland/cooke_optimise.py
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO="$(cd "$HERE/../../.." && pwd)"
GIT_DIR="${1:-/work/.mirror/optiland+optiland/repo}"
DEST="${2:-/work/peers/optiland}"

case "$(realpath -m "$DEST")/" in
  "$REPO"/*) echo "setup.sh: DEST $DEST is inside the repository $REPO; refusing" >&2; exit 1 ;;
esac

if [ ! -e "$DEST/optiland/__init__.py" ]; then
  mkdir -p "$DEST"
  # Skip blobs the snapshot lacks (git archive stops at the first missing one).
  excludes=()
  while read -r path; do
    excludes+=(":(exclude)$path")
  done < <(git --git-dir="$GIT_DIR" ls-tree -r HEAD \
             | awk '$2 == "blob" { print $3 "\t" $4 }' \
             | while IFS=$'\t' read -r sha path; do
                 git --git-dir="$GIT_DIR" cat-file -e "$sha" 2>/dev/null || echo "$path"
               done)
  [ ${#excludes[@]} -gt 0 ] && echo "setup.sh: skipping ${#excludes[@]} missing file(s): ${excludes[*]}"
  git --git-dir="$GIT_DIR" archive HEAD -- . "${excludes[@]}" | tar -x -C "$DEST"
  echo "setup.sh: exported $(git --git-dir="$GIT_DIR" log -1 --format='%H %ci') to $DEST"
fi

if patch -d "$DEST" -p1 -N --dry-run --silent < "$HERE/issue630-cache-key.patch" >/dev/null 2>&1; then
  patch -d "$DEST" -p1 -N < "$HERE/issue630-cache-key.patch"
elif patch -d "$DEST" -p1 -R --dry-run --silent < "$HERE/issue630-cache-key.patch" >/dev/null 2>&1; then
  echo "setup.sh: issue #630 fix already applied"
else
  echo "setup.sh: issue630-cache-key.patch neither applies nor is applied to $DEST" >&2
  exit 1
fi

if [ "${SKIP_APT:-0}" != 1 ]; then
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
    python3-numpy python3-scipy python3-matplotlib python3-pandas python3-yaml \
    python3-tabulate python3-requests python3-numba python3-seaborn
fi

PYTHONPATH="$DEST" /usr/bin/python3 -c \
  'from optiland.samples.objectives import CookeTriplet; print("optiland OK, Cooke EFL", CookeTriplet().paraxial.f2())'
