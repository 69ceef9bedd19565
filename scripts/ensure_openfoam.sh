#!/usr/bin/env bash
# ensure_openfoam.sh [CACHE_DIR]: make OpenFOAM v1912 usable for building the fluid solver.
#
#   1. Debian's `openfoam` package (v1912, double precision, 32-bit labels): libraries in
#      /usr/lib, binaries (blockMesh, pimpleFoam, decomposePar...) in /usr/bin, the run-time
#      configuration in /usr/share/openfoam/etc. It ships no headers.
#   2. The headers of the very same version, from Debian's source package `openfoam`: only
#      src/ and wmake/ are unpacked into CACHE_DIR (default <repo>/build-deps/openfoam-1912),
#      then every library folder of src/ gets its lnInclude/ folder (wmake/wmakeLnInclude).
#      Needs a deb-src entry: when the machine has none, one is derived from the machine's own
#      apt entries (same archives, Types deb-src) in /etc/apt/sources.list.d/fsi-openfoam-src.*
#
# Idempotent: when everything is there it prints nothing and exits 0 at once (a stamp file in
# CACHE_DIR records the version it was made for). Non-interactive (fine with CI=true and no
# standard input). Uses sudo for apt when not run as root. Exit status: 0 ok, 2 failure (the
# message says which step failed and what to do). Log of the last provisioning run:
# CACHE_DIR/provision.log. Build with -DFSI_OPENFOAM_SRC=CACHE_DIR/src (cmake/OpenFOAM.cmake).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
CACHE=${1:-$ROOT/build-deps/openfoam-1912}
STAMP_LAYOUT=2  # bump when the cache layout changes (2: also applications/.../pimpleFoam, our solver starts from it)
WANT_UPSTREAM=1912                      # the OpenFOAM release the project is written against
PKG=openfoam

say() { printf 'ensure_openfoam: %s\n' "$*" >&2; }
die() {
  printf 'ensure_openfoam: error: %s\n' "$1" >&2
  shift
  for line in "$@"; do printf '  %s\n' "$line" >&2; done
  exit 2
}

installed_src_version() {            # source version of the installed package, empty if none
  local status
  status=$(dpkg-query -W -f='${Status}' "$PKG" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || return 0
  dpkg-query -W -f='${source:Version}' "$PKG" 2>/dev/null || true
}

PIMPLE=applications/solvers/incompressible/pimpleFoam

stamp_text() { printf 'openfoam-src %s layout %s\n' "$1" "$STAMP_LAYOUT"; }

# ---- fast path: nothing to do ---------------------------------------------------------------
srcver=$(installed_src_version)
if [ -n "$srcver" ] && [ -f "$CACHE/.fsi-openfoam-stamp" ] &&
   [ "$(cat "$CACHE/.fsi-openfoam-stamp" 2>/dev/null)" = "$(stamp_text "$srcver")" ] &&
   [ -e "$CACHE/src/finiteVolume/lnInclude/fvCFD.H" ] && [ -e "$CACHE/$PIMPLE/pimpleFoam.C" ]; then
  exit 0
fi

# ---- slow path ------------------------------------------------------------------------------
mkdir -p "$CACHE" || die "cannot create the cache folder $CACHE" "choose another: $0 DIR"
CACHE=$(cd "$CACHE" && pwd)
# One provisioning at a time per cache (parallel builds, two ./fsi calls).
exec 9>"$CACHE/.lock"
if command -v flock >/dev/null 2>&1; then
  flock -w 1800 9 || die "timed out waiting for another ensure_openfoam.sh on $CACHE"
fi
# The other one may have done the work meanwhile.
srcver=$(installed_src_version)
if [ -n "$srcver" ] && [ "$(cat "$CACHE/.fsi-openfoam-stamp" 2>/dev/null)" = "$(stamp_text "$srcver")" ] &&
   [ -e "$CACHE/src/finiteVolume/lnInclude/fvCFD.H" ] && [ -e "$CACHE/$PIMPLE/pimpleFoam.C" ]; then
  exit 0
fi
LOG=$CACHE/provision.log
: >"$LOG"

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || die "not root and no sudo: cannot install Debian packages" \
    "as root run: apt-get install openfoam, and add a deb-src entry for apt-get source"
  SUDO="sudo -n"
fi
export DEBIAN_FRONTEND=noninteractive
APT_OPTS=(-q -y -o DPkg::Lock::Timeout=600 -o Dpkg::Use-Pty=0)

run_logged() {  # run_logged STEP CMD...: append output to the log; on failure die with its tail
  local step=$1; shift
  printf '\n$ %s\n' "$*" >>"$LOG"
  if ! "$@" </dev/null >>"$LOG" 2>&1; then
    tail -n 15 "$LOG" | sed 's/^/    | /' >&2
    die "step '$step' failed (full log: $LOG)" "${FIX_HINT:-see the log above}"
  fi
}

# Does apt know any deb-src entry? If not, derive one from the machine's own deb entries.
have_deb_src() {
  apt-get indextargets --format '$(IDENTIFIER)' 2>/dev/null | grep -qx Sources
}
add_deb_src() {
  local d=/etc/apt/sources.list.d tmp
  tmp=$(mktemp)
  local f
  # deb822 files: every stanza whose Types has deb, copied with Types: deb-src.
  for f in "$d"/*.sources; do
    [ -f "$f" ] || continue
    case "$(basename "$f")" in fsi-openfoam-src.sources) continue ;; esac
    awk 'BEGIN { RS = ""; ORS = "\n\n" }
         /(^|\n)Types:[^\n]*(^|[ \t])deb([ \t]|\n|$)/ {
           sub(/(^|\n)Types:[^\n]*/, "\nTypes: deb-src"); sub(/^\n/, ""); print }' "$f" >>"$tmp"
  done
  if [ -s "$tmp" ]; then
    $SUDO install -m 644 "$tmp" "$d/fsi-openfoam-src.sources"
  else
    # one-line format (/etc/apt/sources.list, *.list)
    : >"$tmp"
    for f in /etc/apt/sources.list "$d"/*.list; do
      [ -f "$f" ] || continue
      case "$(basename "$f")" in fsi-openfoam-src.list) continue ;; esac
      sed -n -E 's/^[[:space:]]*deb([[:space:]])/deb-src\1/p' "$f" >>"$tmp"
    done
    [ -s "$tmp" ] || { rm -f "$tmp"; die "no apt entry found to derive a deb-src entry from" \
      "add a deb-src line for the Debian archive to /etc/apt/sources.list, then re-run $0"; }
    $SUDO install -m 644 "$tmp" "$d/fsi-openfoam-src.list"
  fi
  rm -f "$tmp"
  say "added a deb-src entry (derived from this machine's apt entries) in $d/fsi-openfoam-src.*"
}

need_pkg=0
[ -n "$srcver" ] || need_pkg=1
case "$srcver" in ""|"$WANT_UPSTREAM".*) ;; *)
  die "installed $PKG is version $srcver, the project needs OpenFOAM v$WANT_UPSTREAM" \
      "install Debian's $PKG $WANT_UPSTREAM.* (Debian 12 'bookworm' has it)" ;;
esac

say "provisioning OpenFOAM v$WANT_UPSTREAM into $CACHE (log: $LOG)"
t0=$(date +%s)

# Step 1: apt entries and lists (one apt-get update for both the package and its sources).
if ! have_deb_src; then
  FIX_HINT="check /etc/apt/sources.list.d/ and the network to the Debian archive"
  add_deb_src
fi
FIX_HINT="check the apt entries (apt-get update must succeed) and the network to the Debian archive"
say "apt-get update"
# A failing third-party entry must not stop us: what counts is that the package is found below.
$SUDO apt-get "${APT_OPTS[@]}" update </dev/null >>"$LOG" 2>&1 || say "apt-get update reported errors (see $LOG); going on"

# Step 2: the binary package.
if [ "$need_pkg" = 1 ]; then
  cand=$(apt-cache policy "$PKG" 2>/dev/null | sed -n 's/^ *Candidate: *//p')
  case "$cand" in
    "$WANT_UPSTREAM".*) ;;
    ""|"(none)") die "apt knows no package '$PKG'" "this needs Debian 12 (bookworm) with its main archive" ;;
    *) die "apt offers $PKG $cand, the project needs v$WANT_UPSTREAM" "use Debian 12 (bookworm)" ;;
  esac
  say "installing Debian package $PKG $cand (about 66 MB download)"
  FIX_HINT="install it by hand: apt-get install --no-install-recommends $PKG"
  run_logged "apt-get install $PKG" $SUDO apt-get "${APT_OPTS[@]}" install --no-install-recommends "$PKG"
  srcver=$(installed_src_version)
  [ -n "$srcver" ] || die "$PKG is still not installed after apt-get install (log: $LOG)"
fi

# Step 3: the source package of exactly the installed version.
DL=$CACHE/.download
rm -rf "$DL" && mkdir -p "$DL"
say "downloading the source package $PKG=$srcver"
FIX_HINT="needs a deb-src entry and 'apt-get update'; try: cd $DL && apt-get source --download-only $PKG=$srcver"
(cd "$DL" && run_logged "apt-get source $PKG=$srcver" \
  apt-get -q -o APT::Sandbox::User=root source --download-only "$PKG=$srcver")
orig=$(ls "$DL"/*.orig.tar.* 2>/dev/null | head -n 1)
[ -n "$orig" ] || die "no upstream tarball (*.orig.tar.*) in $DL after apt-get source (log: $LOG)"

# Step 4: unpack src/ and wmake/ only (about 80 MB) into a fresh tree, then swap it in.
say "unpacking src/ and wmake/ of $(basename "$orig")"
rm -rf "$CACHE/.unpack" "$CACHE/src" "$CACHE/wmake" "$CACHE/applications" "$CACHE/.fsi-openfoam-stamp"
mkdir -p "$CACHE/.unpack"
FIX_HINT="is there room in $CACHE (about 100 MB)? the tarball is $orig"
run_logged "unpack sources" tar -xf "$orig" -C "$CACHE/.unpack" --no-same-owner --strip-components=1 \
  --wildcards --no-wildcards-match-slash '*/src' '*/wmake' "*/$PIMPLE"
[ -d "$CACHE/.unpack/src/OpenFOAM" ] && [ -x "$CACHE/.unpack/wmake/wmakeLnInclude" ] &&
  [ -e "$CACHE/.unpack/$PIMPLE/pimpleFoam.C" ] ||
  die "the tarball $orig has no src/OpenFOAM, wmake/wmakeLnInclude or $PIMPLE"

# Step 5: lnInclude folders (relative links, so the cache can be moved) for every library.
say "creating lnInclude folders"
FIX_HINT="run by hand: $CACHE/.unpack/wmake/wmakeLnInclude -s <library folder>"
count=0
while IFS= read -r make; do
  run_logged "wmakeLnInclude ${make%/Make}" "$CACHE/.unpack/wmake/wmakeLnInclude" -s "${make%/Make}"
  count=$((count + 1))
done < <(find "$CACHE/.unpack/src" -type d -name Make -not -path '*/lnInclude/*' | sort)
[ -e "$CACHE/.unpack/src/finiteVolume/lnInclude/fvCFD.H" ] ||
  die "lnInclude creation did not produce finiteVolume/lnInclude/fvCFD.H (log: $LOG)"
mv "$CACHE/.unpack/src" "$CACHE/src"
mv "$CACHE/.unpack/wmake" "$CACHE/wmake"
mv "$CACHE/.unpack/applications" "$CACHE/applications"
rm -rf "$CACHE/.unpack" "$DL"

stamp_text "$srcver" >"$CACHE/.fsi-openfoam-stamp"
say "done in $(( $(date +%s) - t0 )) s: $count libraries, headers in $CACHE/src ($(du -sh "$CACHE" | cut -f1))"
