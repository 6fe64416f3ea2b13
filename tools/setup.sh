#!/usr/bin/env bash
# ochre set-up: installs the Debian 12 packages ochre needs (idempotent, non-interactive),
# then configures and builds Release into build/ (executables in build/bin/).
# Usage: bash tools/setup.sh            (install + build everything: tools and tests)
#        bash tools/setup.sh ochre      (install + build only the given targets, e.g. the renderer: the
#                                        quickest way to a first render, 152 of 333 compilations)
#        OCHRE_SKIP_APT=1 bash tools/setup.sh   (build only)
set -euo pipefail
cd "$(dirname "$0")/.."

# Build: compilers, CMake, Ninja and the libraries of CMakeLists.txt (libexpat1-dev: ochre-regress reads
# JUnit files; libnlopt-dev: NLopt's SLSQP for ochre-fit's bounded least squares; libpugixml-dev: Mitsuba 3
# XML scenes, docs/mitsuba-import.md; pybind11-dev, python3-dev: the Python module, docs/python.md);
# openimageio-tools because Debian's OpenImageIO CMake config refuses to load without its executables
# (iinfo, oiiotool, ...). Tests: libgtest-dev (Debian's GTest config needs no gmock). Plots of ochre-brdf /
# ochre-converge / ochre-fit
# (tools/scripts/plot_*.py): python3 with numpy and matplotlib.
PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libopenimageio-dev openimageio-tools libopencolorio-dev libembree-dev libopenexr-dev
  libimath-dev libosd-dev libtbb-dev libassimp-dev nlohmann-json3-dev libcli11-dev libfmt-dev libexpat1-dev
  libnlopt-dev libpugixml-dev libgtest-dev python3 python3-numpy python3-matplotlib pybind11-dev python3-dev
  # Browser tests of ochre-regress's HTML report (tests/browser): headless Chromium, its WebDriver, and
  # Selenium for /usr/bin/python3 (the test is skipped without them).
  chromium chromium-driver python3-selenium
  # Fuzzing (tests/fuzz, tools/dev/fuzz.sh): clang with libFuzzer and the sanitizer runtimes.
  clang-14 libfuzzer-14-dev libclang-rt-14-dev
  # The Slurm tests (tests/cli/slurm: a one-node cluster on 127.0.0.1, tools/scripts/one_node_cluster.sh): the
  # daemons, the client commands and munge; nothing is started at installation on a machine without systemd,
  # and on one with systemd only munge.service (slurmd and slurmctld need /etc/slurm/slurm.conf).
  slurmctld slurmd slurm-client munge
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${OCHRE_SKIP_APT:-0}" != 1 ] && [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "ochre setup: installing ${missing[*]}"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
if [ $# -gt 0 ]; then
  cmake --build build -j "$(nproc)" --target "$@"
else
  cmake --build build -j "$(nproc)"
fi
