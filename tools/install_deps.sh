#!/usr/bin/env bash
# Installs the Debian 12 packages that building, running and testing need, only those missing
# (a no-op taking well under a second when everything is present). Needs root or sudo.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config clang-format clang libclang-rt-14-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools spirv-tools
  libx11-dev libxext-dev libxrandr-dev libglm-dev libglfw3-dev libtinygltf-dev libopenimageio-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libimgui-dev python3-matplotlib
  libopenvdb-dev libopenvdb-tools
  xvfb xauth
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

sudo=""
if [[ $(id -u) -ne 0 ]]; then
  if ! command -v sudo >/dev/null; then
    echo "install_deps: missing packages (${missing[*]}) and not root; run as root" >&2
    exit 1
  fi
  sudo="sudo"
fi
echo "install_deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
