#!/usr/bin/env bash
# Installs what rstruct needs from Debian packages, and only what is missing.
# Non-interactive, idempotent, fast when everything is present. Run as root.
set -euo pipefail

packages=(
  meson ninja-build g++ pkg-config python3
  libgmp-dev libboost-dev libeigen3-dev
  catch2 librapidcheck-dev
  libmpfi-dev libmpfr-dev
  libnanoflann-dev libcli11-dev nlohmann-json3-dev libtbb-dev
)
# clang and its sanitizer/fuzzer runtimes only where fuzzing is asked for.
if [[ "${RSTRUCT_FUZZ:-0}" == 1 ]]; then packages+=(clang libclang-rt-14-dev); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
if [[ $(id -u) -ne 0 ]]; then
  SUDO=sudo
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
