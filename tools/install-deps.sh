#!/bin/sh
# Installs what the project needs from Debian, only what is missing (idempotent), then writes
# ./freefem++.pref so that a plain `FreeFem++ edp/scenes/<scene>.edp` run from the repository
# root finds the stock plugins and .idp files: Debian's /etc/freefem++.pref points at
# /usr/lib/ff++/4.9/..., which does not exist (the files are in /usr/lib/freefem++ and
# /usr/include/freefem++/idp). tools/ff sets the same paths through FF_LOADPATH/FF_INCLUDEPATH.
set -eu
unset CDPATH  # (a user's CDPATH would send the relative cd below elsewhere: tools/ff says more)
root=$(cd -- "$(dirname "$0")/.." && pwd)

# python3-getfem is used only by make bench and tests/getfem_lame_test.py (tools/bench/oracles/getfem_lame.py:
# ring-lame solved by GetFEM, the independent solver our pressure and speed are compared with):
# 16.7 MB with libgetfem5 and libqhull8.0, plus python3-scipy (62 MB) where it is not installed yet.
# python3-pandas, python3-pip, python3-setuptools and python3-wheel: the sma package (python/sma,
# `make python`: an editable install, offline, by Debian's pip and setuptools; its DataFrames).
# libsuitesparse-dev: CHOLMOD's nested-dissection ordering, which the plugin's sparse LDL' uses
# above 50 000 unknowns (plugin/core/sparse_spd.hpp).
# jupyter-nbconvert (the `jupyter nbconvert` command, with python3-nbconvert, -nbclient, -nbformat)
# and python3-ipykernel (the Python kernel, /usr/share/jupyter/kernels/python3 running
# /usr/bin/python3): the lab notebook docs/tutorial/sleeve-lab.ipynb, executed headless by
# tests/tutorial_test.py (`jupyter nbconvert --to notebook --execute`): 51 packages, 27 MB installed
# with IPython, zmq and tornado on Debian 12. jupyter-notebook (the browser front end) is not
# needed for that; `make lab` installs it (tools/install-deps.sh jupyter-notebook).
packages="freefem++ libfreefem++-dev gmsh libeigen3-dev libsuitesparse-dev libgtest-dev libsiconos-numerics-dev cmake make g++
python3-matplotlib python3-numpy python3-vtk9 openmpi-bin python3-getfem python3-pandas python3-pip
python3-setuptools python3-wheel jupyter-nbconvert python3-ipykernel python3-nbformat python3-nbclient"

# Arguments name packages wanted besides (make lab: jupyter-notebook, the browser front end).
packages="$packages $*"

# One dpkg-query for every package (one per package took a second, on every make target).
installed=$(dpkg-query -W -f='${Package} ${Status}\n' $packages 2>/dev/null || true)
missing=""
for p in $packages; do
  case "
$installed
" in
    *"
$p install ok installed
"*) ;;
    *) missing="$missing $p" ;;
  esac
done

if [ -n "$missing" ]; then
  echo "install-deps: installing$missing"
  if [ "$(id -u)" = 0 ]; then sudo=""; else sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing
fi

stock_plugins=/usr/lib/freefem++
stock_idp=/usr/include/freefem++/idp
for f in "$stock_plugins/iovtk.so" "$stock_idp/getARGV.idp"; do
  [ -e "$f" ] || { echo "install-deps: $f is missing after installing freefem++" >&2; exit 1; }
done

pref="$root/freefem++.pref"
# FreeFEM's pref file quotes each path with double quotes and knows no escape: a checkout whose
# path holds one gets no pref file (tools/ff passes the paths itself, so the scenes still run).
case "$root" in
  *\"*|*"
"*)
    rm -f "$pref"
    echo "install-deps: the checkout's path holds a double quote or a line break: no ./freefem++.pref written (run scenes with tools/ff)" >&2
    exit 0 ;;
esac
# The project's .idp folders: edp/lib (errors, output, meshes), edp/model (the material law),
# edp/solvers (DC, heat, contact, DCT), edp/problems (the sleeve's setup, time loop and report).
new=$(printf 'loadpath += "./"\nloadpath += "%s/plugin/build"\nloadpath += "%s"\nincludepath += "%s/edp/lib"\nincludepath += "%s/edp/model"\nincludepath += "%s/edp/solvers"\nincludepath += "%s/edp/problems"\nincludepath += "%s"\n' \
  "$root" "$stock_plugins" "$root" "$root" "$root" "$root" "$stock_idp")
if [ ! -f "$pref" ] || [ "$(cat "$pref")" != "$new" ]; then
  printf '%s\n' "$new" > "$pref"
fi
