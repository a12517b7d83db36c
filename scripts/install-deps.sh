#!/usr/bin/env bash
# Installs vlo's Debian build and test dependencies when missing. Idempotent: quick when all present.
set -euo pipefail
PKGS=(build-essential cmake pkg-config xz-utils
      librosbag-storage-dev pluginlib-dev libsensor-msgs-dev libgeometry-msgs-dev libnav-msgs-dev libtf2-msgs-dev  # ROS 1 bags (vlo-import rosbag)
      libmrpt-dev mrpt-apps libopencv-dev libceres-dev libpcl-dev libeigen3-dev
      nlohmann-json3-dev libcli11-dev libnanoflann-dev  # JSON files, command lines, kd-tree (LOAM)
      libgtest-dev libbenchmark-dev libgl-dev libegl-dev parallel
      python3  # the e2e scripts read CSV with its csv module
      clang-format  # scripts/check-format.sh (CI): the code keeps .clang-format
      libjpeg62-turbo-dev  # jpeglib.h: the rawlog reader turns libjpeg errors into exceptions
      libegl-mesa0 libgl1-mesa-dri)  # headless rendering (EGL + llvmpipe) for the simulator and snapshots
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
