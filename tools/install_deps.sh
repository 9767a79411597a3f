#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian packages pednav needs, only those that are missing.
#   tools/install_deps.sh [--java] [extra packages...]
# --java adds the JDK and JUnit 5 for the optional Java binding (bindings/java).
set -euo pipefail
packages=(build-essential cmake pkg-config libeigen3-dev nlohmann-json3-dev doctest-dev valgrind python3-jsonschema
          python3-numpy python3-cffi python3-pytest python3-matplotlib python3-dask python3-distributed)
extra=()
for a in "$@"; do
  if [ "$a" = "--java" ]; then packages+=(default-jdk junit5); else extra+=("$a"); fi
done
missing=()
for p in "${packages[@]}" "${extra[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  # env, not a prefix assignment: sudo resets the environment of its command.
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi
