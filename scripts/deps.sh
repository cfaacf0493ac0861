#!/usr/bin/env bash
# Installs the Debian packages this repository needs, and nothing when all are present.
# libopenblas0-pthread becomes the system BLAS (update-alternatives): CHOLMOD's supernodal
# factorisation of the BFS matrix (n = 128, 64516 unknowns, 3.2 GFlop) took 1.21 s with the
# reference BLAS and 0.37-0.67 s with OpenBLAS on this 2-core machine.
# libpetsc-real-dev (PETSc 3.18, for the peer of `make bench` and its agreement test) brings 79
# packages, about 240 MiB installed (OpenMPI, MUMPS, HYPRE, Trilinos among them); on this machine
# apt-get installed them in 12 s from a warm cache.
# Usage: scripts/deps.sh   (called by `make deps`; root or sudo, otherwise prints the apt-get line)
set -euo pipefail

packages=(
  g++ make cmake pkg-config time  # time: GNU time, which scripts/step.sh reads each step's cost with
  libeigen3-dev libsuitesparse-dev libmuparser-dev libcli11-dev nlohmann-json3-dev
  libopenblas0-pthread libblas3  # libblas3: the reference BLAS, for the FreeFEM out-of-memory test
  libgtest-dev libgmock-dev libbenchmark-dev
  freefem++ libfreefem++ gmsh
  pandoc gnuplot-nox fonts-dejavu-extra
  libpetsc-real-dev
  chromium poppler-utils  # the document printed as a reader's browser prints it: its page count is tested
)

missing=()
for p in "${packages[@]}"; do
  # dpkg-query is exact about "installed"; a removed-but-configured package does not count.
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "deps: missing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  sudo=(sudo)
else
  echo "deps: not root and no password-less sudo; run this as root:" >&2
  echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update
"${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
