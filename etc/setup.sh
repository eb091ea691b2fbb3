#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
# Installs everything the project needs on a bare Debian 12 machine, idempotently:
# the Debian packages (OpenFOAM v1912, LIGGGHTS 3.8.0, Open MPI), and the OpenFOAM headers and
# wmake from Debian's openfoam source package, cached under $VFM_CACHE (default ~/.cache/voidFraction).
# A second run takes seconds.
set -eu
say() { printf '[setup] %s\n' "$*"; }
need_pkgs="openfoam libopenfoam liggghts libliggghts-dev openmpi-bin libopenmpi-dev g++ make flex python3-numpy python3-matplotlib libscotch-dev libptscotch-dev libmetis-dev"
sudo_=""; [ "$(id -u)" = 0 ] || sudo_="sudo"

missing=""
for p in $need_pkgs; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    say "installing Debian packages:$missing"
    $sudo_ apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_ apt-get install -y -qq $missing >/dev/null
else
    say "Debian packages present"
fi

cache="${VFM_CACHE:-$HOME/.cache/voidFraction}"
src="$cache/openfoam-src"
mkdir -p "$cache"
if [ ! -f "$src/.unpacked" ]; then
    if ! ls "$cache"/openfoam_*.orig.tar.* >/dev/null 2>&1; then
        say "fetching Debian's openfoam source package (headers and wmake, ~45 MB)"
        list=/etc/apt/sources.list.d/voidfraction-src.sources
        if [ ! -f "$list" ]; then
            printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
                | $sudo_ tee "$list" >/dev/null
            $sudo_ apt-get update -qq
        fi
        (cd "$cache" && apt-get source --download-only -qq openfoam >/dev/null)
    fi
    say "unpacking the OpenFOAM source tree"
    rm -rf "$src" && mkdir -p "$src"
    tar -xf "$(ls "$cache"/openfoam_*.orig.tar.* | head -n1)" -C "$src" --strip-components=1
    touch "$src/.unpacked"
fi

# the lnInclude folders the project's builds need; a list that grows is
# prepared again
libs="OpenFOAM OSspecific/POSIX finiteVolume meshTools fileFormats surfMesh Pstream/mpi lagrangian/basic
      dynamicMesh parallel/decompose/decompositionMethods TurbulenceModels/turbulenceModels
      TurbulenceModels/incompressible TurbulenceModels/phaseIncompressible"
if [ ! -f "$src/.prepared" ] || [ "$(cat "$src/.prepared")" != "$(echo $libs)" ]; then
    say "building wmake helpers and lnInclude folders"
    (
        set +eu
        export WM_MPLIB=SYSTEMOPENMPI WM_COMPILER_TYPE=system WM_LABEL_SIZE=32 \
               WM_PRECISION_OPTION=DP WM_COMPILE_OPTION=Opt
        . "$src/etc/bashrc" >/dev/null 2>&1
        set -e
        cd "$src/wmake/src" && ./Allmake >/dev/null
        cd "$src/src"
        for lib in $libs; do
            wmakeLnInclude -u "$lib" >/dev/null
        done
    )
    echo $libs > "$src/.prepared"
fi
say "ready: OpenFOAM source at $src"
